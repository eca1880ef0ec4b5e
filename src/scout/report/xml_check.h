#ifndef SCOUT_REPORT_XML_CHECK_H_
#define SCOUT_REPORT_XML_CHECK_H_

// Test helper: a minimal well-formedness check for the SVG Scout writes
// (elements, quoted attributes, entities, comments); not a general parser.

#include <cctype>
#include <map>
#include <string>
#include <vector>

namespace scout::report::testing {

struct XmlCheck {
  std::string error;                   // empty when well-formed
  std::map<std::string, int> counts;   // elements by tag name
  std::map<std::string, int> classes;  // elements by class attribute
};

inline bool ValidEntity(const std::string& text, size_t amp) {
  for (const char* e : {"&amp;", "&lt;", "&gt;", "&quot;", "&#39;"}) {
    if (text.compare(amp, std::string(e).size(), e) == 0) return true;
  }
  return false;
}

inline XmlCheck CheckXml(const std::string& text) {
  XmlCheck result;
  std::vector<std::string> open;
  size_t i = 0;
  int roots = 0;
  const auto fail = [&](const std::string& what) {
    result.error = what + " at offset " + std::to_string(i);
    return result;
  };
  while (i < text.size()) {
    if (text[i] == '&' && !ValidEntity(text, i)) return fail("bad entity");
    if (text[i] != '<') {
      if (open.empty() && !std::isspace(static_cast<unsigned char>(text[i]))) {
        return fail("text outside the root element");
      }
      ++i;
      continue;
    }
    if (text.compare(i, 4, "<!--") == 0) {
      const size_t end = text.find("-->", i);
      if (end == std::string::npos) return fail("unterminated comment");
      i = end + 3;
      continue;
    }
    const size_t end = text.find('>', i);
    if (end == std::string::npos) return fail("unterminated tag");
    std::string tag = text.substr(i + 1, end - i - 1);
    if (tag.empty()) return fail("empty tag");
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1)) return fail("mismatched </" + tag + ">");
      open.pop_back();
      i = end + 1;
      continue;
    }
    const bool self_closing = tag.back() == '/';
    if (self_closing) tag.pop_back();
    size_t p = 0;
    while (p < tag.size() && !std::isspace(static_cast<unsigned char>(tag[p]))) ++p;
    const std::string name = tag.substr(0, p);
    // Attributes: name="value" pairs, values without '<' or '"'.
    while (p < tag.size()) {
      while (p < tag.size() && std::isspace(static_cast<unsigned char>(tag[p]))) ++p;
      if (p == tag.size()) break;
      const size_t eq = tag.find('=', p);
      if (eq == std::string::npos || eq + 1 >= tag.size() || tag[eq + 1] != '"') {
        return fail("attribute without quoted value in <" + name + ">");
      }
      const std::string attribute = tag.substr(p, eq - p);
      const size_t close = tag.find('"', eq + 2);
      if (close == std::string::npos) return fail("unterminated attribute value");
      const std::string value = tag.substr(eq + 2, close - eq - 2);
      if (value.find('<') != std::string::npos) return fail("'<' in attribute value");
      for (size_t a = value.find('&'); a != std::string::npos; a = value.find('&', a + 1)) {
        if (!ValidEntity(value, a)) return fail("bad entity in attribute");
      }
      if (attribute == "class") ++result.classes[value];
      p = close + 1;
    }
    if (open.empty() && ++roots > 1) return fail("second root element");
    ++result.counts[name];
    if (!self_closing) open.push_back(name);
    i = end + 1;
  }
  if (!open.empty()) return fail("unclosed <" + open.back() + ">");
  if (roots != 1) return fail("no root element");
  return result;
}

}  // namespace scout::report::testing

#endif  // SCOUT_REPORT_XML_CHECK_H_
