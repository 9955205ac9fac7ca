// The page of `glint serve` (web/*.html, *.js, *.css), embedded in the binary at build time by
// cmake/embed_web_assets.cmake, so the server reads no file to serve it.
#pragma once

#include <string_view>
#include <vector>

namespace glint {

struct WebAsset {
    std::string_view path;          // "/index.html", "/app.js", …
    std::string_view content_type;  // "text/html; charset=utf-8", …
    std::string_view bytes;
};

const std::vector<WebAsset>& web_assets();

// The asset at exactly `path` ("/" is "/index.html"), or nullptr: nothing else is ever served.
const WebAsset* find_web_asset(std::string_view path);

}  // namespace glint
