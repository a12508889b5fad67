// tiershade base: base64 (RFC 4648 section 4, the standard alphabet with '=' padding), for the float
// arrays exchanged with a browser page (glue/browser/webgl_conform.*: the page's atob/btoa).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

std::string base64_encode(const void *data, size_t n);
// False on a character outside the alphabet, a length that is not a multiple of 4, or padding
// anywhere but at the end; *out holds the bytes otherwise.
bool base64_decode(const std::string &s, std::vector<uint8_t> *out);
