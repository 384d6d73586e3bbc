# The build tree mirrors an installed prefix, so the program finds its data relative to itself in
# both (lib/resources/resource_paths.hpp): share/impactbench/{scenarios,scripts,fclib,lcp_siconos}
# are links
# to the source folders here, so an edited scenario takes effect without a rebuild.
set(impactbench_build_share ${PROJECT_BINARY_DIR}/share/impactbench)
file(MAKE_DIRECTORY ${impactbench_build_share})
foreach(link_and_source IN ITEMS "scenarios=scenarios" "scripts=tools" "fclib=tests/data/fclib"
       "lcp_siconos=tests/data/lcp_siconos")
  string(REPLACE "=" ";" parts ${link_and_source})
  list(GET parts 0 link)
  list(GET parts 1 source)
  file(REMOVE ${impactbench_build_share}/${link})
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${source} ${impactbench_build_share}/${link} SYMBOLIC)
endforeach()
