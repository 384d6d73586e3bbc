"""Line styles for plots that put engines side by side. No engine is named here: the engines are
whatever the program wrote (the registry in tools/engines/registry is the only list of engine
names), styled by their position in the sorted list of the engines in one plot, so a new engine
needs no edit here. The reference line of a comparison keeps a style of its own."""

COLORS = ["tab:blue", "tab:orange", "tab:green", "tab:purple", "tab:brown", "tab:pink",
          "tab:olive", "tab:cyan", "tab:gray"]
LINESTYLES = ["--", "-.", ":"]
MARKERS = ["o", "s", "^", "v", "D", "P", "X", "*", "h"]
# The analytic solution, drawn over the engines.
REFERENCE_STYLE = dict(color="tab:red", linewidth=1.0, linestyle="-")


def line_styles(engines):
    """{engine: matplotlib keyword arguments} for trajectories of the given engines."""
    styles = {}
    for i, engine in enumerate(sorted(engines)):
        styles[engine] = dict(color=COLORS[i % len(COLORS)], linewidth=1.4,
                              linestyle=LINESTYLES[i % len(LINESTYLES)])
    return styles


def marker_formats(engines):
    """{engine: matplotlib format string} (marker and solid line) for the given engines."""
    return {engine: MARKERS[i % len(MARKERS)] + "-" for i, engine in enumerate(sorted(engines))}
