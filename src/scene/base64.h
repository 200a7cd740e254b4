#pragma once
// Base64 (RFC 4648, standard alphabet, with padding) for glTF data: URIs.
#include <optional>
#include <string>
#include <vector>

namespace hipr {

std::string base64_encode(const std::vector<unsigned char>& bytes);
// nullopt when `text` is not valid base64.
std::optional<std::vector<unsigned char>> base64_decode(const std::string& text);

}  // namespace hipr
