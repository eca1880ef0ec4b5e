#ifndef SCOUT_IO_YAML_FIELDS_H_
#define SCOUT_IO_YAML_FIELDS_H_

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

namespace scout::io {

// Reads the fields of one YAML mapping into option structs, naming the file
// and the full key ("frontier.epsilon_m") in every error; rejects keys it was
// not asked for, so a misspelt option never passes silently.
class YamlSection {
 public:
  enum class Bound { kInclusive, kExclusive };

  // 'node' must be a mapping (or absent/null: then nothing is read) whose
  // keys are scalars, none given twice.
  YamlSection(const YAML::Node& node, std::string file, std::string prefix);

  // Each Read* leaves 'value' unchanged when the key is absent. Throws
  // InputError when the value has the wrong type or is out of range.
  void ReadDouble(const std::string& key, double* value);
  void ReadPositive(const std::string& key, double* value);
  void ReadNonNegative(const std::string& key, double* value);
  // A finite number in [min, max], (min, max), [min, max) or (min, max].
  void ReadInRange(const std::string& key, double* value, double min, double max, Bound min_bound,
                   Bound max_bound);
  // Shorthands: a number in [0, max], and one in (0, max]. Lengths and times
  // that the loop works through cell by cell or step by step need an upper
  // bound: 1e300 would exhaust memory or never finish a step.
  void ReadNonNegativeAtMost(const std::string& key, double* value, double max) {
    ReadInRange(key, value, 0.0, max, Bound::kInclusive, Bound::kInclusive);
  }
  void ReadPositiveAtMost(const std::string& key, double* value, double max) {
    ReadInRange(key, value, 0.0, max, Bound::kExclusive, Bound::kInclusive);
  }
  void ReadInt(const std::string& key, int* value, int min_value,
               int max_value = std::numeric_limits<int>::max());
  void ReadBool(const std::string& key, bool* value);
  // A sequence of [x, y] pairs of finite numbers (an empty sequence clears
  // 'points').
  void ReadPoints(const std::string& key, std::vector<Eigen::Vector2d>* points);
  // Returns the sub-section 'key' (possibly empty).
  YamlSection Section(const std::string& key);
  // Throws InputError naming the first key that no Read*/Section asked for.
  void RejectUnknownKeys() const;

 private:
  std::string Name(const std::string& key) const;
  YAML::Node Take(const std::string& key);

  YAML::Node node_;
  std::string file_;
  std::string prefix_;
  std::vector<std::string> seen_;
};

}  // namespace scout::io

#endif  // SCOUT_IO_YAML_FIELDS_H_
