// load_scenario: reads a scenario file section by section (format: scenarios/README.md) and
// validates every value, so that engines can trust a Scenario without further checks.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <set>

#include "lib/output/message_text.hpp"
#include "lib/scenario/load_context.hpp"
#include "lib/scenario/named_expressions.hpp"
#include "lib/scenario/scenario.hpp"
#include "lib/scenario/scenario_functions.hpp"

namespace impactbench::scenario {

namespace {

// Names that expressions provide themselves; no parameter, derived or analytic name may hide them.
const std::set<std::string>& reserved_names() {
  static const std::set<std::string> names = {
      "t",     "i",     "k",     "duration", "floor", "ceil", "mod",  "rad",     "rand",
      "sin",   "cos",   "tan",   "asin",     "acos",  "atan", "sinh", "cosh",    "tanh",
      "asinh", "acosh", "atanh", "log2",     "log10", "log",  "ln",   "exp",     "sqrt",
      "sign",  "rint",  "abs",   "min",      "max",   "sum",  "avg",  "tri_row", "tri_col"};
  return names;
}

bool is_identifier(const std::string& name) {
  if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])))) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

std::string join(const std::vector<std::string>& items, const std::string& separator = ", ") {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

std::string number(double value) {
  return output::number_text(value);
}

/// Tracks every name defined in [parameters], [derived] and [analytic] to reject clashes.
class NameRegistry {
 public:
  explicit NameRegistry(const LoadContext& context) : context_(context) {}
  void add(const std::string& name, int line, const std::string& field) {
    if (!is_identifier(name))
      context_.fail(
          line, field,
          "'" + name + "' is not a valid name (letters, digits, _; starts with a letter)");
    if (reserved_names().count(name))
      context_.fail(line, field, "'" + name + "' is reserved for expressions");
    if (!names_.insert(name).second) context_.fail(line, field, "'" + name + "' is defined twice");
  }

 private:
  const LoadContext& context_;
  std::set<std::string> names_;
};

std::vector<Parameter> read_parameters(const LoadContext& context, const TableReader& root,
                                       NameRegistry& registry) {
  const DocumentNode& table = root.required("parameters");
  const TableReader must_be_a_table(context, table, "parameters.");
  std::vector<Parameter> out;
  for (const auto& [name, node] : table.entries) {
    registry.add(name, node.line, "parameters." + name);
    TableReader entry(context, node, "parameters." + name + ".");
    entry.allow_only({"default", "unit", "description"});
    const DocumentNode& value = entry.required("default");
    expect_kind(context, value, DocumentNode::Kind::kNumber, entry.field("default"));
    if (!std::isfinite(value.number))
      context.fail(value.line, entry.field("default"), "must be finite");
    out.push_back(
        {name, value.number, value.number, entry.string("unit"), entry.string("description")});
  }
  if (std::none_of(out.begin(), out.end(), [](const Parameter& p) { return p.name == "g"; }))
    context.fail(table.line, "parameters.g",
                 "missing required parameter (gravitational acceleration)");
  return out;
}

void apply_overrides(const LoadContext& context, std::vector<Parameter>& parameters,
                     const ParameterOverrides& overrides) {
  for (const auto& [name, value] : overrides) {
    auto it = std::find_if(parameters.begin(), parameters.end(),
                           [&](const Parameter& p) { return p.name == name; });
    if (it == parameters.end()) {
      std::vector<std::string> valid;
      for (const auto& p : parameters) valid.push_back(p.name);
      context.fail(0, "--set " + name, "unknown parameter (valid: " + join(valid) + ")");
    }
    if (!std::isfinite(value)) context.fail(0, "--set " + name, "value must be finite");
    it->value = value;
  }
}

/// [derived]: named expressions of the parameters (and of each other), evaluated once.
void read_derived(LoadContext& context, const TableReader& root, NameRegistry& registry) {
  const DocumentNode* table = root.optional("derived");
  if (!table) return;
  const TableReader must_be_a_table(context, *table, "derived.");
  VariableTable variables = context.make_variables();
  for (const auto& [name, node] : table->entries) {
    registry.add(name, node.line, "derived." + name);
    variables.define(name);
  }
  NamedExpressions expressions(variables);
  for (const auto& [name, node] : table->entries) {
    Expression expression = context.compile(node, "derived." + name, variables);
    context.derived_reads[name] = expression.used_variables();
    expressions.add(name, std::move(expression));
  }
  if (const auto cycle = expressions.find_cycle(); !cycle.empty())
    context.fail(table->find(cycle.front())->line, "derived." + cycle.front(),
                 "circular definition " + join(cycle, " -> "));
  // A value that is not finite for the user's parameters (t_first with g = 0) is kept: it is
  // an error only in a field that reads it, which then names the parameter (LoadContext::blame).
  for (auto& named_value : expressions.evaluate_all())
    context.named_values.push_back(std::move(named_value));
}

double read_positive(const LoadContext& context, const TableReader& root, const std::string& key) {
  VariableTable variables = context.make_variables();
  const DocumentNode& node = root.required(key);
  const Expression expression = context.compile(node, key, variables);
  const double value = context.finite_value(expression, node, root.field(key));
  if (!(value > 0.0))
    context.fail(node.line, key,
                 "must be > 0 (got " + number(value) + ")" + context.blame(expression));
  return value;
}

/// The file's duration when --duration replaces it: still a well-formed expression, and a
/// constant one (0, inf, -0.0 written in the file: it reads no name) still finite and > 0, so that
/// a file that `describe` refuses is refused by every command. A formula is not evaluated:
/// parameters given with --set may make it vanish, and the flag is then the way to run the
/// scenario.
void check_replaced_duration(const LoadContext& context, const TableReader& root) {
  VariableTable variables = context.make_variables();
  const DocumentNode& node = root.required("duration");
  const Expression expression = context.compile(node, "duration", variables);
  if (!expression.used_variables().empty()) return;
  const double value = context.finite_value(expression, node, root.field("duration"));
  if (!(value > 0.0))
    context.fail(node.line, "duration",
                 "must be > 0 (got " + number(value) + ")" + context.blame(expression));
}

/// The file's `dt` and `tolerance` as every engine it lists takes them (`tolerance = 10` is out
/// of the engines' range): bad data in the file, refused with its line like any other field.
void check_run_values(const LoadContext& context, const TableReader& root, const Scenario& scenario,
                      bool duration_given) {
  for (const std::string field : {"dt", "tolerance"}) {
    // A step against a --duration is the caller's to check: the flag, not the file, is wrong.
    if (field == "dt" && duration_given) continue;
    const double value = field == "dt" ? scenario.dt : scenario.tolerance;
    for (const std::string& engine : scenario.engines) {
      const std::string problem =
          context.engines->run_value_problem(engine, field, value, scenario.duration);
      if (problem.empty()) continue;
      // Messages of the step count name their engine already.
      const bool named = problem.rfind(engine + ": ", 0) == 0;
      context.fail(root.required(field).line, field, named ? problem : engine + ": " + problem);
    }
  }
}

std::vector<std::string> read_engines(const LoadContext& context, const TableReader& root) {
  const DocumentNode& node = root.required("engines");
  expect_kind(context, node, DocumentNode::Kind::kArray, "engines");
  if (node.items.empty()) context.fail(node.line, "engines", "must list at least one engine");
  std::vector<std::string> engines;
  for (std::size_t i = 0; i < node.items.size(); ++i) {
    const std::string field = "engines[" + std::to_string(i) + "]";
    expect_kind(context, node.items[i], DocumentNode::Kind::kString, field);
    const std::string& engine = node.items[i].text;
    const auto& known = context.engines->engine_names();
    if (std::find(known.begin(), known.end(), engine) == known.end())
      context.fail(node.items[i].line, field,
                   "unknown engine '" + engine + "' (known: " + join(known) + ")");
    if (std::find(engines.begin(), engines.end(), engine) != engines.end())
      context.fail(node.items[i].line, field, "engine '" + engine + "' listed twice");
    engines.push_back(engine);
  }
  return engines;
}

model::Material read_material(const LoadContext& context, const TableReader& root) {
  TableReader table(context, root.required("material"), "material.");
  table.allow_only({"friction", "restitution"});
  VariableTable variables = context.make_variables();
  const auto read = [&](const std::string& key) {
    const DocumentNode& node = table.required(key);
    return context.finite_value(context.compile(node, table.field(key), variables), node,
                                table.field(key));
  };
  model::Material material;
  material.friction = read("friction");
  if (material.friction < 0.0)
    context.fail(table.required("friction").line, "material.friction",
                 "friction coefficient must be >= 0 (got " + number(material.friction) + ")");
  material.restitution = read("restitution");
  if (material.restitution < 0.0 || material.restitution > 1.0)
    context.fail(table.required("restitution").line, "material.restitution",
                 "restitution must be in [0, 1] (got " + number(material.restitution) + ")");
  return material;
}

/// A unit direction from a vector field (normal of a plane, direction of an input).
Eigen::Vector3d read_direction(const LoadContext& context, const TableReader& table,
                               const std::string& key) {
  VariableTable variables = context.make_variables();
  const DocumentNode& node = table.required(key);
  const auto parts =
      compile_vector(context, node, table.field(key), context.vector_size(), variables);
  const Eigen::Vector3d direction = evaluate_vector(context, parts, node, table.field(key));
  if (!(direction.norm() > 1e-12)) context.fail(node.line, table.field(key), "must not be zero");
  return direction.normalized();
}

std::vector<model::StaticPlaneSpec> read_planes(const LoadContext& context,
                                                const TableReader& root) {
  std::vector<model::StaticPlaneSpec> planes;
  const DocumentNode* node = root.optional("planes");
  if (!node) return planes;
  expect_kind(context, *node, DocumentNode::Kind::kArray, "planes");
  for (std::size_t index = 0; index < node->items.size(); ++index) {
    TableReader table(context, node->items[index], "planes[" + std::to_string(index) + "].");
    table.allow_only({"name", "point", "normal"});
    model::StaticPlaneSpec plane;
    plane.name = table.optional_string("name", "plane" + std::to_string(index));
    VariableTable variables = context.make_variables();
    const DocumentNode& point = table.required("point");
    plane.point = evaluate_vector(
        context,
        compile_vector(context, point, table.field("point"), context.vector_size(), variables),
        point, table.field("point"));
    plane.normal = read_direction(context, table, "normal");
    planes.push_back(plane);
  }
  return planes;
}

void read_inputs(const LoadContext& context, const TableReader& root, Scenario& scenario,
                 ScenarioFunctions& functions) {
  const DocumentNode* node = root.optional("inputs");
  VariableTable& variables = functions.input_variables();
  for (const auto& [name, value] : context.named_values) variables.define(name, value);
  variables.define("t");
  if (!node) return;
  expect_kind(context, *node, DocumentNode::Kind::kArray, "inputs");
  for (std::size_t index = 0; index < node->items.size(); ++index) {
    TableReader table(context, node->items[index], "inputs[" + std::to_string(index) + "].");
    table.allow_only({"body", "direction", "force"});
    model::ForceInputSpec input;
    input.body = table.string("body");
    if (!scenario.find_body(input.body))
      context.fail(table.required("body").line, table.field("body"),
                   "no body named '" + input.body + "'");
    input.direction = read_direction(context, table, "direction");
    const DocumentNode& force = table.required("force");
    Expression expression = context.compile(force, table.field("force"), variables);
    for (const double t : {0.0, scenario.duration}) {  // catch NaN-producing formulas early
      variables.at("t") = t;
      context.finite_value(expression, force, table.field("force"), " at t = " + number(t));
    }
    functions.add_input(std::move(expression));
    scenario.inputs.push_back(input);
  }
}

void read_analytic(const LoadContext& context, const TableReader& root, NameRegistry& registry,
                   Scenario& scenario, ScenarioFunctions& functions) {
  VariableTable& variables = functions.analytic_variables();
  for (const auto& [name, value] : context.named_values) variables.define(name, value);
  variables.define("k");
  variables.define("duration", scenario.duration);
  const DocumentNode* table = root.optional("analytic");
  if (!table) return;
  const TableReader must_be_a_table(context, *table, "analytic.");
  for (const auto& [name, node] : table->entries) {
    registry.add(name, node.line, "analytic." + name);
    variables.define(name);
  }
  for (const auto& [name, node] : table->entries) {
    AnalyticQuantity quantity{name, "", "", "", false};
    const DocumentNode* expression_node = &node;
    std::string field = "analytic." + name;
    if (node.kind == DocumentNode::Kind::kTable) {
      TableReader entry(context, node, field + ".");
      entry.allow_only({"expression", "unit", "description"});
      expression_node = &entry.required("expression");
      quantity.unit = entry.optional_string("unit", "");
      quantity.description = entry.optional_string("description", "");
      field += ".expression";
    }
    Expression expression = context.compile(*expression_node, field, variables);
    quantity.expression = expression.source();
    functions.analytic().add(name, std::move(expression));
    scenario.analytic_quantities.push_back(quantity);
  }
  if (const auto cycle = functions.analytic().find_cycle(); !cycle.empty())
    context.fail(table->find(cycle.front())->line, "analytic." + cycle.front(),
                 "circular definition " + join(cycle, " -> "));
}

/// An analytic quantity is indexed when it reads k itself or through another quantity.
void mark_indexed(Scenario& scenario, const ScenarioFunctions& functions) {
  for (auto& quantity : scenario.analytic_quantities)
    quantity.indexed = functions.analytic_reads(quantity.name, "k");
}

void check_plank_box(const LoadContext& context, const TableReader& root,
                     const Scenario& scenario) {
  const DocumentNode& table = root.required("parameters");
  for (const char* name : {"m_B", "L_B", "l_B", "m_P", "L_P", "l_P"}) {
    const Parameter* p = scenario.find_parameter(name);
    if (!p)
      context.fail(table.line, std::string("parameters.") + name, "required by system plank_box");
    if (!(p->value > 0.0))
      context.fail(table.find(name)->line, std::string("parameters.") + name,
                   "must be > 0 (got " + number(p->value) + ")");
  }
  for (const char* name : {"k_P", "b_P"}) {
    const Parameter* p = scenario.find_parameter(name);
    if (!p)
      context.fail(table.line, std::string("parameters.") + name, "required by system plank_box");
    if (p->value < 0.0)
      context.fail(table.find(name)->line, std::string("parameters.") + name,
                   "must be >= 0 (got " + number(p->value) + ")");
  }
  for (const char* body : {"box", "plank"})
    if (!scenario.find_body(body))
      context.fail(root.required("bodies").line, "bodies",
                   std::string("system plank_box needs a body named '") + body + "'");
}

template <typename Enum>
Enum read_choice(const LoadContext& context, const TableReader& root, const std::string& key,
                 const std::vector<std::pair<std::string, Enum>>& choices) {
  const std::string value = root.string(key);
  std::vector<std::string> names;
  for (const auto& [name, choice] : choices) {
    if (name == value) return choice;
    names.push_back("\"" + name + "\"");
  }
  context.fail(root.required(key).line, key, "'" + value + "' is not one of " + join(names));
}

}  // namespace

Scenario load_scenario(const EngineCatalog& engines, const std::filesystem::path& path,
                       const ParameterOverrides& overrides, std::optional<double> duration) {
  LoadContext context;
  context.path = path.string();
  context.engines = &engines;
  const DocumentNode document = parse_document(path);
  const TableReader root(context, document, "");
  root.allow_only({"name", "description", "dimension", "system", "engines", "duration", "dt",
                   "tolerance", "reference_trajectory", "settings", "parameters", "derived",
                   "material", "bodies", "planes", "inputs", "analytic"});

  Scenario scenario;
  scenario.path = path;
  scenario.name = root.string("name");
  if (scenario.name != path.stem().string())
    context.fail(root.required("name").line, "name",
                 "'" + scenario.name + "' must match the file name '" + path.stem().string() + "'");
  scenario.description = root.string("description");
  scenario.dimension =
      read_choice<Dimension>(context, root, "dimension",
                             {{"planar", Dimension::kPlanar}, {"spatial", Dimension::kSpatial}});
  context.dimension = scenario.dimension;
  scenario.system = read_choice<SystemKind>(
      context, root, "system",
      {{"rigid_bodies", SystemKind::kRigidBodies}, {"plank_box", SystemKind::kPlankBox}});
  scenario.engines = read_engines(context, root);

  NameRegistry registry(context);
  scenario.parameters = read_parameters(context, root, registry);
  apply_overrides(context, scenario.parameters, overrides);
  context.overrides.assign(overrides.begin(), overrides.end());
  for (const auto& p : scenario.parameters) context.named_values.emplace_back(p.name, p.value);
  read_derived(context, root, registry);

  // Material first: a bad --set restitution should be reported as such, not through a
  // duration formula that depends on it.
  scenario.material = read_material(context, root);
  if (duration) {
    check_replaced_duration(context, root);
    if (!(std::isfinite(*duration) && *duration > 0.0))
      context.fail(0, "--duration", "must be finite and > 0 (got " + number(*duration) + ")");
    scenario.duration = *duration;
  } else {
    scenario.duration = read_positive(context, root, "duration");
  }
  scenario.dt = read_positive(context, root, "dt");
  if (!duration && scenario.dt > scenario.duration)  // with --duration the caller checks it
    context.fail(
        root.required("dt").line, "dt",
        "step " + number(scenario.dt) + " exceeds the duration " + number(scenario.duration));
  scenario.tolerance = read_positive(context, root, "tolerance");
  check_run_values(context, root, scenario, duration.has_value());
  scenario.reference_trajectory = root.optional_boolean("reference_trajectory", true);
  scenario.engine_settings = read_engine_settings(context, root, scenario);

  const double g = scenario.parameter("g");
  scenario.gravity = scenario.dimension == Dimension::kPlanar ? Eigen::Vector3d(0.0, -g, 0.0)
                                                              : Eigen::Vector3d(0.0, 0.0, -g);
  scenario.bodies = read_bodies(context, root.required("bodies"));
  scenario.planes = read_planes(context, root);

  auto functions = std::make_shared<ScenarioFunctions>();
  read_inputs(context, root, scenario, *functions);
  read_analytic(context, root, registry, scenario, *functions);
  mark_indexed(scenario, *functions);
  if (scenario.system == SystemKind::kPlankBox) check_plank_box(context, root, scenario);
  scenario.functions = std::move(functions);
  return scenario;
}

}  // namespace impactbench::scenario
