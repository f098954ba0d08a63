#include "test_filters.h"

#include <darkroom/core/registry.h>
#include <gtest/gtest.h>

#include <string>

using namespace darkroom;

namespace {
std::string fixture(const std::string& name) {
    return std::string(DARKROOM_FIXTURE_PLUGIN_DIR) + "/darkroom-fixture-" + name + ".so";
}
std::string allMessages(const Diagnostics& d) {
    std::string s;
    for (const auto& x : d) s += x.str() + "\n";
    return s;
}
}  // namespace

TEST(Registry, LoadsAGoodPlugin) {
    Registry r;
    Diagnostics d;
    ASSERT_TRUE(r.loadPlugin(fixture("good"), d)) << allMessages(d);
    EXPECT_TRUE(d.empty());
    ASSERT_NE(r.filter("FixtureScale"), nullptr);
    EXPECT_EQ(r.filter("FixtureScale")->origin.plugin, "fixture-good");
    EXPECT_EQ(r.filter("FixtureScale")->origin.path, fixture("good"));
    ASSERT_EQ(r.plugins().size(), 1u);
    EXPECT_EQ(r.plugins()[0].sdkVersion, DARKROOM_SDK_VERSION);
    EXPECT_EQ(r.ports("FixtureScale").inputs.size(), 2u);
}

TEST(Registry, RefusesAPluginBuiltForAnotherAbiAndGoesOn) {
    Registry r;
    const Diagnostics d = r.loadPlugins({fixture("wrong-abi"), fixture("good")});
    ASSERT_EQ(d.size(), 1u) << allMessages(d);
    EXPECT_EQ(d[0].where, fixture("wrong-abi"));
    const std::string expectedVersions = "ABI version " + std::to_string(DARKROOM_ABI_VERSION + 98) +
                                         ", but this host uses ABI version " + std::to_string(DARKROOM_ABI_VERSION);
    EXPECT_NE(d[0].message.find(expectedVersions), std::string::npos) << d[0].message;
    EXPECT_NE(r.filter("FixtureScale"), nullptr) << "the good plugin after the bad one still loads";
    EXPECT_EQ(r.plugins().size(), 1u);
}

TEST(Registry, SkipsAPluginWhoseRegistrationThrows) {
    Registry r;
    Diagnostics d;
    EXPECT_FALSE(r.loadPlugin(fixture("throwing"), d));
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NE(d[0].message.find("fixture registration failure"), std::string::npos) << d[0].message;
    EXPECT_EQ(r.filter("FixtureNeverVisible"), nullptr) << "partial registrations are rolled back";
    EXPECT_TRUE(r.plugins().empty());
}

TEST(Registry, DuplicateTypeNamesNameBothFiles) {
    Registry r;
    const Diagnostics d = r.loadPlugins({fixture("good"), fixture("duplicate")});
    ASSERT_EQ(d.size(), 1u) << allMessages(d);
    EXPECT_NE(d[0].message.find("duplicate filter type 'FixtureScale'"), std::string::npos) << d[0].message;
    EXPECT_NE(d[0].message.find(fixture("good")), std::string::npos) << d[0].message;
    EXPECT_NE(d[0].message.find(fixture("duplicate")), std::string::npos) << d[0].message;
    EXPECT_EQ(r.filter("FixtureScale")->origin.plugin, "fixture-good");
}

TEST(Registry, ReportsMissingFilesAndNonPlugins) {
    Registry r;
    Diagnostics d;
    EXPECT_FALSE(r.loadPlugin("/nonexistent/darkroom-nothing.so", d));
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NE(d[0].message.find("cannot load plugin"), std::string::npos);
    // The SDK library is a shared object but not a plugin.
    const std::string sdk = std::string(DARKROOM_BINARY_DIR) + "/lib/libdarkroom-sdk.so";
    EXPECT_FALSE(r.loadPlugin(sdk, d));
    ASSERT_EQ(d.size(), 2u);
    EXPECT_NE(d[1].message.find("not a Darkroom plugin"), std::string::npos) << d[1].message;
}

TEST(Registry, DirectoriesLoadInSortedOrderOnce) {
    Registry r;
    const Diagnostics d = r.loadPlugins({DARKROOM_FIXTURE_PLUGIN_DIR, DARKROOM_FIXTURE_PLUGIN_DIR});
    // duplicate (sorted before good) wins FixtureScale; good is then the duplicate;
    // wrong-abi and throwing fail, and the four misbehaving fixtures of
    // test_plugin_isolation.cpp are quarantined. Listing the folder twice
    // loads nothing twice.
    EXPECT_EQ(d.size(), 7u) << allMessages(d);
    EXPECT_EQ(r.filter("FixtureScale")->origin.plugin, "fixture-duplicate");
}

TEST(Registry, SearchPathOrderIsExeDirThenEnvThenExtra) {
    ::setenv("DARKROOM_PLUGIN_PATH", "/env/one:/env/two", 1);
    const auto path = Registry::defaultSearchPath({"/extra"});
    ::unsetenv("DARKROOM_PLUGIN_PATH");
    ASSERT_GE(path.size(), 3u);
    EXPECT_EQ(path[path.size() - 3], "/env/one");
    EXPECT_EQ(path[path.size() - 2], "/env/two");
    EXPECT_EQ(path.back(), "/extra");
}

TEST(Registry, BuiltinDuplicatesThrow) {
    Registry r;
    r.registerBuiltin("test", &testfilters::registerAll);
    EXPECT_THROW(r.registerBuiltin("again", &testfilters::registerAll), Error);
    EXPECT_THROW(r.createFilter("NoSuchType"), Error);
}
