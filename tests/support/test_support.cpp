#include "test_support.h"

#include <darkroom/error.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace darkroom::test {

namespace {
// Poisoned planes in every test process: a pixel a pass leaves unwritten
// (Fill::None) shows as a NaN pattern instead of stale memory. Set before
// main(), so before the plane pool first reads it.
const bool g_poison = [] { return ::setenv("DARKROOM_POISON_PLANES", "1", 0) == 0; }();
}  // namespace

Registry& pluginRegistry() {
    static Registry* registry = [] {
        auto* r = new Registry();
        const Diagnostics d = r->loadPlugins({DARKROOM_TEST_PLUGIN_DIR});
        for (const auto& x : d) ADD_FAILURE() << x.str();
        return r;
    }();
    return *registry;
}

std::string sharedData(const std::string& relative) {
    const fs::path p = fs::path(DARKROOM_SHARED_DATA_DIR) / relative;
    return fs::exists(p) ? p.string() : std::string();
}

TempDir::TempDir() {
    std::string tmpl = (fs::temp_directory_path() / "darkroom-test-XXXXXX").string();
    if (!::mkdtemp(tmpl.data())) throw Error("cannot create a temporary directory");
    path_ = tmpl;
}

TempDir::~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

std::shared_ptr<WritableBuffer> makeImage(int w, int h, const std::vector<std::string>& channels,
                                          const std::function<float(int, int, int)>& fn) {
    std::vector<ChannelDesc> desc;
    for (const auto& c : channels) desc.push_back({c, ChannelType::Float32});
    auto b = makeCpuBuffer(w, h, desc);
    for (std::size_t c = 0; c < channels.size(); ++c) {
        float* p = b->writeFloat(channels[c]);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) p[std::size_t(y) * w + x] = fn(x, y, int(c));
    }
    return b;
}

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string compareFolders(const std::string& a, const std::string& b) {
    namespace fs = std::filesystem;
    const auto files = [](const std::string& folder) {
        std::set<std::string> names;
        for (const auto& e : fs::recursive_directory_iterator(folder))
            if (!e.is_directory()) names.insert(fs::relative(e.path(), folder).string());
        return names;
    };
    const auto na = files(a), nb = files(b);
    if (na != nb) {
        std::string d = "the folders hold different files:";
        for (const auto& n : na)
            if (!nb.count(n)) d += " " + n + " (only in " + a + ")";
        for (const auto& n : nb)
            if (!na.count(n)) d += " " + n + " (only in " + b + ")";
        return d;
    }
    std::string d;
    for (const auto& n : na)
        if (readText(a + "/" + n) != readText(b + "/" + n)) d += (d.empty() ? "" : ", ") + n;
    return d.empty() ? d : "these files differ: " + d;
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

}  // namespace darkroom::test
