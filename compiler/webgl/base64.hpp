// Base64 (RFC 4648, standard alphabet, padded) for the bytes that cross the DevTools pipe as
// JSON strings: textures, blocks and meshes to the page, read-back pixels and screenshots from it.
#pragma once
#include <string>
#include <string_view>

namespace mb::webgl {

std::string base64Encode(std::string_view bytes);
// Skips characters outside the alphabet (padding, line breaks).
std::string base64Decode(std::string_view text);

}  // namespace mb::webgl
