// What a C++ identifier may be: the package's C++ header names its namespace after
// `compile --namespace` and declares every material parameter as a struct member.
#pragma once
#include <string>

namespace mb {

// A C++20 keyword or alternative token (ISO/IEC 14882:2020 [lex.key], [lex.digraph]).
bool isCppKeyword(const std::string& name);

// Why `name` cannot be the header's namespace, or empty when it can: one identifier or a
// nested `a::b` whose every part is [A-Za-z_][A-Za-z0-9_]*, no C++ keyword, and none of the
// names the standard reserves for the implementation ([lex.name]: containing "__", or "_"
// and an upper-case letter first).
std::string cppNamespaceRefusal(const std::string& name);

}  // namespace mb
