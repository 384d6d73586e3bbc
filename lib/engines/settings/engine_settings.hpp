#pragma once
// An engine's settings as a schema (its fields over its options struct) and as the command
// line, the scenario loader and the run summary see every engine alike (EngineSettings): the
// keys it accepts, which keys the flags --dt, --tol and --solver set, and one function that
// turns what was given into every setting in force with its source.
#include <any>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "lib/engines/settings/setting_fields.hpp"

namespace impactbench::engines {

struct SettingKey {
  std::string key;
  std::string accepts;
};

/// What resolving an engine's settings gives: every key in force as text with its source (for
/// reports, `describe` and the run summary) and the engine's options struct parsed once from
/// them (an O of the engine's SettingsSchema<O>), which the engine runs with.
struct ResolvedSettings {
  SettingList in_force;
  std::any options;
};

struct EngineSettings {
  std::string engine;  ///< name as on the command line, as the registry spells it
                       ///< (tools/engines/engine_names.hpp)
  std::string title;   ///< name for people, e.g. "Moreau–Jean"
  std::vector<SettingKey> keys;
  std::vector<std::string> dt_keys;         ///< set by --dt and the scenario's dt; empty: no step
  std::vector<std::string> tolerance_keys;  ///< set by --tol and the scenario's tolerance
  /// The key --solver NAME sets; throws SettingError when no key accepts NAME. Empty: the
  /// engine has no solver choice and refuses --solver.
  std::function<std::string(const std::string& name)> solver_key;
  /// Every key, in order, with its value in force: the defaults overridden by `given` in order
  /// (a later entry wins), and the options struct they make. Throws SettingError for an
  /// unknown key or a refused value.
  std::function<ResolvedSettings(const SettingList& given)> resolve;
  /// The expert set (`--settings expert`): key=value pairs that follow the engine's own
  /// documentation for accurate rigid contact, applied over the defaults and under the
  /// scenario and the command line; never the step. Empty: the engine has none (ours).
  std::vector<std::pair<std::string, std::string>> expert;

  bool has_key(const std::string& key) const;
  std::string key_list() const;  ///< "theta, solver, ..."
  /// What the engine accepts, for messages: "--dt, --tol, --solver and --option KEY=VALUE
  /// with KEY one of ...".
  std::string accepted() const;
};

template <typename O>
class SettingsSchema {
 public:
  SettingsSchema(std::string engine, std::string title, std::vector<SettingField<O>> fields,
                 std::function<void(const O&)> validate = {})
      : engine_(std::move(engine)),
        title_(std::move(title)),
        fields_(std::move(fields)),
        validate_(std::move(validate)) {}

  /// The options struct's defaults with `given` applied in order; throws SettingError.
  O parse(const SettingList& given) const {
    O options{};
    for (const SettingValue& setting : given) {
      const SettingField<O>& f = field(setting.key);
      try {
        f.parse(options, setting.value);
      } catch (const std::invalid_argument& error) {
        throw SettingError(engine_, setting.key, error.what());
      }
    }
    if (validate_) validate_(options);
    return options;
  }

  /// The options struct `given` makes, parsed once, and every field with its value in force
  /// and the source of the last entry of `given` for it.
  ResolvedSettings resolve(const SettingList& given) const {
    O options = parse(given);
    SettingList in_force;
    for (const SettingField<O>& f : fields_) {
      SettingSource source = SettingSource::kDefault;
      for (const SettingValue& setting : given)
        if (setting.key == f.key) source = setting.source;
      in_force.push_back({f.key, f.show(options), source});
    }
    return {std::move(in_force), std::move(options)};
  }

  /// The part of EngineSettings a schema knows; the engine adds what its flags set.
  EngineSettings describe() const {
    EngineSettings info;
    info.engine = engine_;
    info.title = title_;
    for (const SettingField<O>& f : fields_) info.keys.push_back({f.key, f.accepts});
    info.resolve = [this](const SettingList& given) { return resolve(given); };
    return info;
  }

 private:
  const SettingField<O>& field(const std::string& key) const {
    for (const SettingField<O>& f : fields_)
      if (f.key == key) return f;
    std::vector<std::string> keys;
    for (const SettingField<O>& f : fields_) keys.push_back(f.key);
    throw SettingError(engine_, key,
                       "is unknown (" + title_ + " accepts: " + join_names(keys, "and") + ")");
  }

  std::string engine_;
  std::string title_;
  std::vector<SettingField<O>> fields_;
  std::function<void(const O&)> validate_;
};

}  // namespace impactbench::engines
