#include <darkroom/product_database.h>

#include <filesystem>

namespace darkroom {

namespace fs = std::filesystem;

std::string databaseOfProduct(const std::string& product) {
    constexpr int kMaxLevels = 8;  // image/<phi>/<theta>/... and then some
    if (product.empty()) return {};
    std::error_code ec;
    fs::path dir = fs::absolute(fs::path(product), ec);
    if (!fs::is_directory(dir, ec)) dir = dir.parent_path();
    for (int i = 0; i < kMaxLevels && !dir.empty(); ++i, dir = dir.parent_path()) {
        if (fs::is_regular_file(dir / "data.csv", ec)) return dir.string();
        if (dir == dir.parent_path()) break;
    }
    return {};
}

}  // namespace darkroom
