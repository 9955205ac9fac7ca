#include "glint/serve/web_assets.hpp"

namespace glint {

const WebAsset* find_web_asset(std::string_view path) {
    if (path == "/") {
        path = "/index.html";
    }
    for (const WebAsset& asset : web_assets()) {
        if (asset.path == path) {
            return &asset;
        }
    }
    return nullptr;
}

}  // namespace glint
