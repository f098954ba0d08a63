// Misbehaving plugins, tried as an adversary would: each is reported naming
// its file and skipped, and the host goes on loading the good one after it.
#include <darkroom/core/registry.h>
#include <gtest/gtest.h>

#include "test_support.h"

#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>

using namespace darkroom;
namespace fs = std::filesystem;

namespace {

std::string fixture(const std::string& name) {
    return std::string(DARKROOM_FIXTURE_PLUGIN_DIR) + "/darkroom-fixture-" + name + ".so";
}

std::string allMessages(const Diagnostics& d) {
    std::string s;
    for (const auto& x : d) s += x.str() + "\n";
    return s;
}

// Each test scans with a cache of its own, so verdicts are computed here.
class PluginIsolation : public ::testing::Test {
protected:
    void SetUp() override { ::setenv("DARKROOM_PLUGIN_CACHE", dir_.file("scan.tsv").c_str(), 1); }
    void TearDown() override { ::unsetenv("DARKROOM_PLUGIN_CACHE"); }

    // Loads `bad` then the good fixture; expects one error naming `bad` that
    // contains `why`, and the good plugin loaded.
    void expectSkipped(const std::string& bad, const std::string& why) {
        Registry r;
        const Diagnostics d = r.loadPlugins({fixture(bad), fixture("good")});
        ASSERT_EQ(d.size(), 1u) << allMessages(d);
        EXPECT_EQ(d[0].where, fixture(bad));
        EXPECT_NE(d[0].message.find(why), std::string::npos) << d[0].message;
        EXPECT_NE(r.filter("FixtureScale"), nullptr) << "the good plugin after the bad one still loads";
    }
    test::TempDir dir_;
};

}  // namespace

TEST_F(PluginIsolation, AnExceptionFromTheEntryPointIsNamed) {
    expectSkipped("entry-throws", "exception escaped");
}

TEST_F(PluginIsolation, AnExceptionFromARawRegisterFunctionIsNamed) {
    expectSkipped("register-throws", "fixture: raw register throws");
}

TEST_F(PluginIsolation, ExitInAStaticConstructorIsQuarantined) {
    expectSkipped("exits-on-load", "ended the process while loading");
}

TEST_F(PluginIsolation, ACrashWhileRegisteringIsQuarantined) {
    expectSkipped("crashes-on-register", "crashed while loading or registering");
}

TEST_F(PluginIsolation, VerdictsAreCachedUntilTheFileChanges) {
    {
        Registry r;
        r.loadPlugins({fixture("crashes-on-register")});
    }
    const std::string cache = test::readText(dir_.file("scan.tsv"));
    EXPECT_NE(cache.find("quarantined"), std::string::npos) << cache;
    EXPECT_NE(cache.find("darkroom-fixture-crashes-on-register.so"), std::string::npos) << cache;
    // A copy is another file: it is probed on its own.
    const std::string copy = dir_.file("darkroom-copy.so");
    fs::copy_file(fixture("good"), copy);
    Registry r;
    const Diagnostics d = r.loadPlugins({copy});
    EXPECT_TRUE(d.empty()) << allMessages(d);
    EXPECT_NE(test::readText(dir_.file("scan.tsv")).find("darkroom-copy.so"), std::string::npos);
}

TEST_F(PluginIsolation, ASymlinkLoopInAPluginFolderIsReportedAndSkipped) {
    const fs::path folder = dir_.file("plugins");
    fs::create_directories(folder);
    fs::create_symlink(folder / "darkroom-loop.so", folder / "darkroom-loop.so");
    fs::copy_file(fixture("good"), folder / "darkroom-good.so");
    Registry r;
    const Diagnostics d = r.loadPlugins({folder.string()});
    ASSERT_EQ(d.size(), 1u) << allMessages(d);
    EXPECT_NE(d[0].where.find("darkroom-loop.so"), std::string::npos) << d[0].str();
    EXPECT_NE(r.filter("FixtureScale"), nullptr);
}

// A host that needs some node types (`darkroom run` of a pipeline) loads
// only the plugins that register them, and the capture backends only when
// it asks for them; the scan cache records each plugin's types, and a cache
// written before it did is probed again to learn them. The rest can still
// be loaded.
TEST_F(PluginIsolation, OnlyThePluginsOfTheWantedTypesAreLoaded) {
    const std::set<std::string> wanted{"ColorMapping", "CinemaReader"};
    const auto check = [&] {
        Registry r;
        const Diagnostics d = r.loadPlugins(Registry::defaultSearchPath(), &wanted);
        EXPECT_TRUE(d.empty()) << allMessages(d);
        EXPECT_NE(r.filter("ColorMapping"), nullptr);
        EXPECT_NE(r.filter("CinemaReader"), nullptr);
        EXPECT_EQ(r.filter("Movie"), nullptr);
        EXPECT_EQ(r.filter("SSAO"), nullptr);
        EXPECT_EQ(r.backend("embree"), nullptr);
        EXPECT_GT(r.setAside(), 10u);
        EXPECT_TRUE(r.loadSetAside().empty());
        EXPECT_NE(r.filter("Movie"), nullptr);
        EXPECT_EQ(r.setAside(), 0u);
    };
    check();  // probed now
    {
        // A pipeline that captures asks for the backends as well.
        const std::set<std::string> capturing{"Capture", Registry::kEveryCaptureBackend};
        Registry r;
        EXPECT_TRUE(r.loadPlugins(Registry::defaultSearchPath(), &capturing).empty());
        EXPECT_NE(r.filter("Capture"), nullptr);
        EXPECT_NE(r.backend("embree"), nullptr);
        EXPECT_EQ(r.filter("ColorMapping"), nullptr);
    }
    const std::string cache = test::readText(dir_.file("scan.tsv"));
    EXPECT_NE(cache.find("\ttypes=ColorMapping\n"), std::string::npos) << cache;
    EXPECT_NE(cache.find("\ttypes=backend:embree\n"), std::string::npos) << cache;
    check();  // from the cache
    // A cache without types, as written before they were recorded.
    std::string old;
    std::istringstream in(cache);
    for (std::string line; std::getline(in, line);) old += line.substr(0, line.find("\ttypes=")) + "\n";
    test::writeText(dir_.file("scan.tsv"), old);
    check();
    EXPECT_NE(test::readText(dir_.file("scan.tsv")).find("\ttypes=ColorMapping\n"), std::string::npos);
}

// A plugin whose types the probe cannot list (here: built for another ABI,
// which the host refuses by itself) is always loaded, and its verdict is
// kept as it is: the scan does not probe it again at every start.
TEST_F(PluginIsolation, APluginWhoseTypesCannotBeListedIsProbedOnce) {
    const std::set<std::string> wanted{"FixtureScale"};
    {
        Registry r;
        const Diagnostics d = r.loadPlugins({fixture("wrong-abi"), fixture("good")}, &wanted);
        ASSERT_EQ(d.size(), 1u) << allMessages(d);  // loaded, so refused by the host, naming it
        EXPECT_EQ(d[0].where, fixture("wrong-abi"));
        EXPECT_EQ(r.setAside(), 0u);
    }
    const std::string cache = test::readText(dir_.file("scan.tsv"));
    EXPECT_NE(cache.find("darkroom-fixture-wrong-abi.so\t"), std::string::npos) << cache;
    EXPECT_NE(cache.find("\ttypes?\n"), std::string::npos) << cache;
    // From the cache: the same, and the cache is not rewritten.
    Registry again;
    EXPECT_EQ(again.loadPlugins({fixture("wrong-abi"), fixture("good")}, &wanted).size(), 1u);
    EXPECT_EQ(test::readText(dir_.file("scan.tsv")), cache);
}
