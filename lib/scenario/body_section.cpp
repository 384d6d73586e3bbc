// [[bodies]]: one table per body, or per family of bodies with `repeat = "count"`, whose
// fields may use the index i (0 .. count-1) and whose name contains "{i}".
#include <cmath>
#include <optional>
#include <set>

#include <Eigen/Geometry>

#include "lib/model/body_inertia.hpp"
#include "lib/output/message_text.hpp"
#include "lib/scenario/load_context.hpp"

namespace impactbench::scenario {

namespace {

struct ShapeInfo {
  const char* name;
  model::ShapeKind kind;
  Dimension dimension;
  bool round;  // radius (disk, sphere) rather than size (box, cuboid)
};

constexpr ShapeInfo kShapes[] = {
    {"disk", model::ShapeKind::kDisk, Dimension::kPlanar, true},
    {"box", model::ShapeKind::kBox, Dimension::kPlanar, false},
    {"sphere", model::ShapeKind::kSphere, Dimension::kSpatial, true},
    {"cuboid", model::ShapeKind::kCuboid, Dimension::kSpatial, false},
};

const ShapeInfo& read_shape(const TableReader& table) {
  const std::string shape = table.string("shape");
  const DocumentNode& node = table.required("shape");
  const auto& context = table.context();
  for (const auto& info : kShapes) {
    if (shape != info.name) continue;
    if (info.dimension != context.dimension)
      context.fail(node.line, table.field("shape"),
                   "'" + shape + "' is not a " + to_string(context.dimension) + " shape");
    return info;
  }
  context.fail(
      node.line, table.field("shape"),
      "unknown shape '" + shape + "' (known: disk, box for planar; sphere, cuboid for spatial)");
}

/// A field compiled once and evaluated for every index i.
struct CompiledScalar {
  const DocumentNode* node = nullptr;
  std::string field;
  std::optional<Expression> expression;
};
struct CompiledVector {
  const DocumentNode* node = nullptr;
  std::string field;
  std::vector<Expression> parts;
};

/// Everything of one [[bodies]] table, compiled against the parameters and i.
class BodyTemplate {
 public:
  BodyTemplate(const LoadContext& context, const DocumentNode& node, std::size_t index)
      : context_(context),
        table_(context, node, "bodies[" + std::to_string(index) + "]."),
        variables_(context.make_variables({"i"})) {
    table_.allow_only({"name", "repeat", "shape", "radius", "size", "mass", "position", "angle",
                       "orientation", "velocity", "angular_velocity", "inertia"});
    name_ = table_.string("name");
    shape_ = &read_shape(table_);
    read_repeat();
    read_geometry();
    mass_ = scalar("mass", true);
    position_ = vector("position", true, context.vector_size());
    velocity_ = vector("velocity", false, context.vector_size());
    if (context.dimension == Dimension::kPlanar) {
      reject("orientation", "only for spatial scenarios; use angle");
      reject("inertia", "only for spatial scenarios");
      angle_ = scalar("angle", false);
      spin_ = scalar("angular_velocity", false);
    } else {
      reject("angle", "only for planar scenarios; use orientation = [w, x, y, z]");
      orientation_ = vector("orientation", false, 4);
      angular_velocity_ = vector("angular_velocity", false, 3);
      inertia_ = vector("inertia", false, 3);
    }
  }

  int count() const { return count_; }

  model::BodySpec instantiate(int i) {
    variables_.at("i") = i;
    const std::string where = repeated_ ? " at i = " + std::to_string(i) : "";
    model::BodySpec body;
    body.name = instance_name(i);
    body.shape = shape_->kind;
    if (shape_->round) {
      body.radius = positive(radius_, where);
    } else {
      body.size = size(where);
      const int components = context_.vector_size();
      for (int c = 0; c < components; ++c)
        if (!(body.size[c] > 0.0))
          context_.fail(
              size_.node->line, size_.field,
              "side lengths must be > 0 (got " + std::to_string(body.size[c]) + ")" + where);
    }
    body.mass = positive(mass_, where);
    body.position = evaluate(position_, where);
    body.velocity = evaluate(velocity_, where);
    if (context_.dimension == Dimension::kPlanar) {
      body.angle = value(angle_, 0.0, where);
      body.orientation =
          Eigen::Quaterniond(Eigen::AngleAxisd(body.angle, Eigen::Vector3d::UnitZ()));
      body.angular_velocity = Eigen::Vector3d(0.0, 0.0, value(spin_, 0.0, where));
    } else {
      body.orientation = quaternion(where);
      body.angular_velocity = evaluate(angular_velocity_, where);
      if (inertia_.node) {
        body.inertia = evaluate(inertia_, where);
        if (const std::string problem = model::inertia_problem(*body.inertia); !problem.empty())
          context_.fail(inertia_.node->line, inertia_.field, problem + where);
      }
    }
    return body;
  }

 private:
  void read_repeat() {
    const DocumentNode* node = table_.optional("repeat");
    if (!node) return;
    repeated_ = true;
    const std::string field = table_.field("repeat");
    const double n =
        context_.finite_value(context_.compile(*node, field, variables_), *node, field);
    if (n < 0 || std::abs(n - std::round(n)) > 1e-9 || n > 1e7)
      context_.fail(node->line, field,
                    "must be a whole number in [0, 1e7] (got " + output::number_text(n) + ")");
    count_ = static_cast<int>(std::lround(n));
    if (name_.find("{i}") == std::string::npos)
      context_.fail(table_.required("name").line, table_.field("name"),
                    "a repeated body needs '{i}' in its name (e.g. \"ball{i}\")");
  }

  void read_geometry() {
    if (shape_->round) {
      reject("size", "a " + std::string(shape_->name) + " takes radius, not size");
      radius_ = scalar("radius", true);
      return;
    }
    reject("radius", "a " + std::string(shape_->name) + " takes size, not radius");
    const DocumentNode& node = table_.required("size");
    size_.node = &node;
    size_.field = table_.field("size");
    if (node.kind == DocumentNode::Kind::kArray) {
      size_.parts = compile_vector(context_, node, size_.field, context_.vector_size(), variables_);
    } else {  // one number: a square or a cube
      cube_size_ = context_.compile(node, size_.field, variables_);
    }
  }

  void reject(const std::string& key, const std::string& why) const {
    if (const DocumentNode* node = table_.optional(key))
      context_.fail(node->line, table_.field(key), why);
  }

  CompiledScalar scalar(const std::string& key, bool required) {
    CompiledScalar out;
    out.field = table_.field(key);
    out.node = required ? &table_.required(key) : table_.optional(key);
    if (out.node) out.expression = context_.compile(*out.node, out.field, variables_);
    return out;
  }

  CompiledVector vector(const std::string& key, bool required, int size) {
    CompiledVector out;
    out.field = table_.field(key);
    out.node = required ? &table_.required(key) : table_.optional(key);
    if (out.node) out.parts = compile_vector(context_, *out.node, out.field, size, variables_);
    return out;
  }

  double value(const CompiledScalar& scalar, double fallback, const std::string& where) const {
    if (!scalar.expression) return fallback;
    return context_.finite_value(*scalar.expression, *scalar.node, scalar.field, where);
  }

  double positive(const CompiledScalar& scalar, const std::string& where) const {
    const double v = value(scalar, 0.0, where);
    if (!(v > 0.0))
      context_.fail(scalar.node->line, scalar.field,
                    "must be > 0 (got " + std::to_string(v) + ")" + where);
    return v;
  }

  /// Full side lengths; a single number means a square (planar) or a cube (spatial).
  Eigen::Vector3d size(const std::string& where) const {
    if (!cube_size_) return evaluate(size_, where);
    const double side = context_.finite_value(*cube_size_, *size_.node, size_.field, where);
    Eigen::Vector3d sides = Eigen::Vector3d::Constant(side);
    if (context_.dimension == Dimension::kPlanar) sides.z() = 0.0;
    return sides;
  }

  Eigen::Vector3d evaluate(const CompiledVector& vector, const std::string& where) const {
    if (!vector.node) return Eigen::Vector3d::Zero();
    return evaluate_vector(context_, vector.parts, *vector.node, vector.field, where);
  }

  Eigen::Quaterniond quaternion(const std::string& where) const {
    if (!orientation_.node) return Eigen::Quaterniond::Identity();
    Eigen::Vector4d wxyz;
    for (int c = 0; c < 4; ++c)
      wxyz[c] = context_.finite_value(orientation_.parts[static_cast<std::size_t>(c)],
                                      orientation_.node->items[static_cast<std::size_t>(c)],
                                      orientation_.field + "[" + std::to_string(c) + "]", where);
    if (!(wxyz.norm() > 1e-12))
      context_.fail(orientation_.node->line, orientation_.field,
                    "a quaternion [w, x, y, z] must not be zero" + where);
    wxyz.normalize();
    return Eigen::Quaterniond(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
  }

  std::string instance_name(int i) const {
    std::string name = name_;
    const std::string index = std::to_string(i);
    for (auto at = name.find("{i}"); at != std::string::npos;
         at = name.find("{i}", at + index.size()))
      name.replace(at, 3, index);
    return name;
  }

  const LoadContext& context_;
  TableReader table_;
  VariableTable variables_;
  std::string name_;
  const ShapeInfo* shape_ = nullptr;
  bool repeated_ = false;
  int count_ = 1;
  CompiledScalar radius_, mass_, angle_, spin_;
  CompiledVector size_, position_, velocity_, orientation_, angular_velocity_, inertia_;
  std::optional<Expression> cube_size_;
};

}  // namespace

std::vector<model::BodySpec> read_bodies(const LoadContext& context, const DocumentNode& bodies) {
  expect_kind(context, bodies, DocumentNode::Kind::kArray, "bodies");
  std::vector<model::BodySpec> out;
  std::set<std::string> names;
  for (std::size_t index = 0; index < bodies.items.size(); ++index) {
    const DocumentNode& node = bodies.items[index];
    BodyTemplate body(context, node, index);
    for (int i = 0; i < body.count(); ++i) {
      out.push_back(body.instantiate(i));
      if (!names.insert(out.back().name).second)
        context.fail(node.line, "bodies[" + std::to_string(index) + "].name",
                     "duplicate body name '" + out.back().name + "'");
    }
  }
  // Every engine integrates at least one body (repeat = 0 everywhere leaves none).
  if (out.empty())
    context.fail(bodies.line, "bodies",
                 "no body to simulate (every repeat count is 0); a scenario needs at least one");
  return out;
}

}  // namespace impactbench::scenario
