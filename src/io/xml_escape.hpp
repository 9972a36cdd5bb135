#pragma once
// Text for an XML attribute or element (the .vtp, .pvd and .xmf writers): the five characters
// XML reserves become their entities.
#include <string>
#include <string_view>

namespace orogen {

inline std::string xml_escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace orogen
