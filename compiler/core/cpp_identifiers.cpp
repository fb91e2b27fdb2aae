#include "core/cpp_identifiers.hpp"

#include <cctype>
#include <iterator>
#include <set>
#include <sstream>

namespace mb {

bool isCppKeyword(const std::string& name) {
  static const std::set<std::string> kKeywords = [] {
    std::istringstream words(
        "alignas alignof and and_eq asm auto bitand bitor bool break case catch char char8_t char16_t char32_t "
        "class compl concept const consteval constexpr constinit const_cast continue co_await co_return co_yield "
        "decltype default delete do double dynamic_cast else enum explicit export extern false float for friend "
        "goto if inline int long mutable namespace new noexcept not not_eq nullptr operator or or_eq private "
        "protected public register reinterpret_cast requires return short signed sizeof static static_assert "
        "static_cast struct switch template this thread_local throw true try typedef typeid typename union "
        "unsigned using virtual void volatile wchar_t while xor xor_eq");
    return std::set<std::string>(std::istream_iterator<std::string>(words), std::istream_iterator<std::string>());
  }();
  return kKeywords.count(name) > 0;
}

std::string cppNamespaceRefusal(const std::string& name) {
  if (name.empty()) return "is empty";
  size_t start = 0;
  while (true) {
    size_t end = name.find("::", start);
    const std::string part = name.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (part.empty()) return "has an empty part: write a C++ identifier or a nested 'a::b'";
    for (size_t i = 0; i < part.size(); ++i) {
      auto c = static_cast<unsigned char>(part[i]);
      if (!(std::isalpha(c) || c == '_' || (i > 0 && std::isdigit(c))))
        return "is not a C++ identifier or a nested 'a::b' of them ([A-Za-z_][A-Za-z0-9_]* each)";
    }
    if (isCppKeyword(part)) return "uses the C++ keyword '" + part + "'";
    if (part.find("__") != std::string::npos ||
        (part[0] == '_' && part.size() > 1 && std::isupper(static_cast<unsigned char>(part[1]))))
      return "uses '" + part +
             "', a name C++ reserves for the implementation (containing '__', or '_' and an "
             "upper-case letter first)";
    if (end == std::string::npos) return {};
    start = end + 2;
  }
}

}  // namespace mb
