#include "scout/io/yaml_fields.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "scout/common/error.h"
#include "scout/common/format.h"

namespace scout::io {

YamlSection::YamlSection(const YAML::Node& node, std::string file, std::string prefix)
    : node_(node), file_(std::move(file)), prefix_(std::move(prefix)) {
  if (node_ && !node_.IsNull() && !node_.IsMap()) {
    throw InputError(file_ + ": '" + (prefix_.empty() ? std::string("(top level)") : prefix_) +
                     "': expected a mapping of option names to values");
  }
  if (!node_ || !node_.IsMap()) return;
  // Take() reads the first of repeated keys: a second one would pass silently.
  std::vector<std::string> keys;
  for (const auto& kv : node_) {
    const std::string where = prefix_.empty() ? std::string("(top level)") : prefix_;
    if (!kv.first.IsScalar()) {
      throw InputError(file_ + ":" + std::to_string(kv.first.Mark().line + 1) + ": '" + where +
                       "': expected option names as keys, got '" + YAML::Dump(kv.first) + "'");
    }
    const std::string key = kv.first.Scalar();
    if (std::find(keys.begin(), keys.end(), key) != keys.end()) {
      throw InputError(file_ + ":" + std::to_string(kv.first.Mark().line + 1) + ": option '" +
                       Name(key) + "' given twice");
    }
    keys.push_back(key);
  }
}

std::string YamlSection::Name(const std::string& key) const {
  return prefix_.empty() ? key : prefix_ + "." + key;
}

YAML::Node YamlSection::Take(const std::string& key) {
  seen_.push_back(key);
  if (!node_ || node_.IsNull()) return YAML::Node(YAML::NodeType::Undefined);
  // Const access: the non-const operator[] would insert the key.
  const YAML::Node& node = node_;
  return node[key];
}

void YamlSection::ReadDouble(const std::string& key, double* value) {
  const YAML::Node n = Take(key);
  if (!n) return;
  try {
    const double v = n.as<double>();
    if (!std::isfinite(v)) throw YAML::Exception(YAML::Mark(), "not finite");
    *value = v;
  } catch (const YAML::Exception&) {
    throw InputError(file_ + ": '" + Name(key) + "': expected a finite number, got '" +
                     YAML::Dump(n) + "'");
  }
}

void YamlSection::ReadPositive(const std::string& key, double* value) {
  double v = *value;
  ReadDouble(key, &v);
  if (!(v > 0.0)) {
    throw InputError(file_ + ": '" + Name(key) + "': expected a positive number, got " +
                     FormatNumber(v));
  }
  *value = v;
}

void YamlSection::ReadNonNegative(const std::string& key, double* value) {
  double v = *value;
  ReadDouble(key, &v);
  if (v < 0.0) {
    throw InputError(file_ + ": '" + Name(key) + "': expected a number >= 0, got " +
                     FormatNumber(v));
  }
  *value = v;
}

void YamlSection::ReadInRange(const std::string& key, double* value, double min, double max,
                              Bound min_bound, Bound max_bound) {
  double v = *value;
  ReadDouble(key, &v);
  const bool above = min_bound == Bound::kInclusive ? v >= min : v > min;
  const bool below = max_bound == Bound::kInclusive ? v <= max : v < max;
  if (!above || !below) {
    std::ostringstream expected;
    expected << (min_bound == Bound::kInclusive ? "[" : "(") << min << ", " << max
             << (max_bound == Bound::kInclusive ? "]" : ")");
    throw InputError(file_ + ": '" + Name(key) + "': expected a number in " + expected.str() +
                     ", got " + FormatNumber(v));
  }
  *value = v;
}

void YamlSection::ReadInt(const std::string& key, int* value, int min_value, int max_value) {
  const YAML::Node n = Take(key);
  if (!n) return;
  int v = 0;
  try {
    v = n.as<int>();
  } catch (const YAML::Exception&) {
    throw InputError(file_ + ": '" + Name(key) + "': expected an integer, got '" + YAML::Dump(n) +
                     "'");
  }
  if (v < min_value || v > max_value) {
    const std::string expected =
        max_value == std::numeric_limits<int>::max()
            ? ">= " + std::to_string(min_value)
            : "from " + std::to_string(min_value) + " to " + std::to_string(max_value);
    throw InputError(file_ + ": '" + Name(key) + "': expected an integer " + expected + ", got " +
                     FormatNumber(v));
  }
  *value = v;
}

void YamlSection::ReadBool(const std::string& key, bool* value) {
  const YAML::Node n = Take(key);
  if (!n) return;
  try {
    *value = n.as<bool>();
  } catch (const YAML::Exception&) {
    throw InputError(file_ + ": '" + Name(key) + "': expected true or false, got '" +
                     YAML::Dump(n) + "'");
  }
}

void YamlSection::ReadPoints(const std::string& key, std::vector<Eigen::Vector2d>* points) {
  const YAML::Node n = Take(key);
  if (!n) return;
  const std::string expected = "expected a sequence of [x, y] pairs of finite numbers";
  if (!n.IsSequence()) {
    throw InputError(file_ + ": '" + Name(key) + "': " + expected + ", got '" + YAML::Dump(n) +
                     "'");
  }
  std::vector<Eigen::Vector2d> read;
  for (size_t i = 0; i < n.size(); ++i) {
    const YAML::Node& pair = n[i];
    Eigen::Vector2d p;
    bool ok = pair.IsSequence() && pair.size() == 2;
    for (int k = 0; ok && k < 2; ++k) {
      try {
        p[k] = pair[k].as<double>();
        ok = std::isfinite(p[k]);
      } catch (const YAML::Exception&) {
        ok = false;
      }
    }
    if (!ok) {
      throw InputError(file_ + ": '" + Name(key) + "': item " + std::to_string(i + 1) + ": " +
                       expected + ", got '" + YAML::Dump(pair) + "'");
    }
    read.push_back(p);
  }
  *points = std::move(read);
}

YamlSection YamlSection::Section(const std::string& key) {
  return YamlSection(Take(key), file_, Name(key));
}

void YamlSection::RejectUnknownKeys() const {
  if (!node_ || !node_.IsMap()) return;
  for (const auto& kv : node_) {
    const std::string key = kv.first.Scalar();
    if (std::find(seen_.begin(), seen_.end(), key) == seen_.end()) {
      std::string known;
      for (const std::string& s : seen_) known += (known.empty() ? "" : ", ") + s;
      throw InputError(file_ + ": unknown option '" + Name(key) + "' (expected one of: " + known +
                       ")");
    }
  }
}

}  // namespace scout::io
