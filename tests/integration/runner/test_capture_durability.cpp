// `darkroom capture` under an LD_PRELOAD shim (tests/shims/fs_call_shim.cpp)
// that logs renames and fsyncs and fails chosen ones: every file is synced
// before it is renamed into place and its folder after, and a sync or close
// that fails stops the capture with the file named, the product unlisted.
#include "runner_process.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

namespace fs = std::filesystem;
using namespace darkroom;
using darkroom::test::runDarkroom;

namespace {

const char* kScene = "objects:\n  - generator: isosurface\n    parameters: {resolution: 16}\n"
                     "cameras:\n  resolution: [32, 32]\n  grid: {phi: 3, theta: 1}\n";

// An AddressSanitizer runtime must come first in the library list: a shim
// preloaded before it stops the process.
bool shimUsable() {
#if defined(__SANITIZE_ADDRESS__)
    return false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    return false;
#else
    return true;
#endif
#else
    return true;
#endif
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}

}  // namespace

TEST(CaptureDurability, EveryFileIsSyncedBeforeItsRenameAndItsFolderAfter) {
    if (!shimUsable()) GTEST_SKIP() << "LD_PRELOAD shims do not mix with AddressSanitizer";
    test::TempDir dir;
    test::writeText(dir.file("s.yaml"), kScene);
    const std::string db = dir.file("db.cdb");
    const auto r = runDarkroom({"capture", dir.file("s.yaml"), "-o", db, "-j", "1"},
                               {"LD_PRELOAD=" DARKROOM_FS_CALL_SHIM, "DARKROOM_SHIM_LOG=" + dir.file("log")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto log = lines(test::readText(dir.file("log")));
    const std::string folder = fs::canonical(db).string();
    std::size_t renames = 0;
    for (std::size_t i = 0; i < log.size(); ++i) {
        if (log[i].rfind("rename ", 0) != 0) continue;
        const fs::path target = log[i].substr(7);
        if (fs::weakly_canonical(target.parent_path()).string() != folder) continue;
        ++renames;
        // The file was synced under its temporary name just before...
        ASSERT_GT(i, 0u);
        EXPECT_EQ(log[i - 1].rfind("fsync " + folder + "/", 0), 0u) << log[i - 1];
        EXPECT_NE(log[i - 1].find(".tmp-"), std::string::npos) << log[i - 1];
        // ...and the folder right after, so the new name survives a crash.
        ASSERT_LT(i + 1, log.size()) << log[i];
        EXPECT_EQ(log[i + 1], "fsync " + folder) << "after " << log[i];
    }
    // The marker, 3 products and data.csv after each of them, and at the start and end.
    EXPECT_GE(renames, 1u + 3u * 2u + 1u);
}

TEST(CaptureDurability, AFailedSyncOrCloseOfAProductStopsTheCaptureUnlisted) {
    if (!shimUsable()) GTEST_SKIP() << "LD_PRELOAD shims do not mix with AddressSanitizer";
    for (const char* variable : {"DARKROOM_SHIM_FAIL_FSYNC", "DARKROOM_SHIM_FAIL_CLOSE"}) {
        test::TempDir dir;
        test::writeText(dir.file("s.yaml"), kScene);
        const std::string db = dir.file("db.cdb");
        const auto r = runDarkroom({"capture", dir.file("s.yaml"), "-o", db, "-j", "1"},
                                   {"LD_PRELOAD=" DARKROOM_FS_CALL_SHIM, std::string(variable) + "=/phi="});
        EXPECT_NE(r.exitCode, 0) << variable;
        EXPECT_NE(r.err.find("cannot write '" + db + "/phi="), std::string::npos) << variable << ": " << r.err;
        EXPECT_NE(r.err.find("Input/output error"), std::string::npos) << variable << ": " << r.err;
        EXPECT_EQ(test::readText(db + "/data.csv"), "phi,theta,FILE\n") << variable;
        for (const auto& f : fs::directory_iterator(db)) {
            const std::string name = f.path().filename().string();
            EXPECT_TRUE(name == "data.csv" || name == ".darkroom-database") << variable << " left " << name;
        }
    }
}
