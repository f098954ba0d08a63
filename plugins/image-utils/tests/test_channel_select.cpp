// ChannelSelect: order, rename, drop, errors.
#include "run_node.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using namespace darkroom;
using namespace darkroom::test;
using ::testing::HasSubstr;

namespace {
std::shared_ptr<WritableBuffer> image() {
    auto b = makeCpuBuffer(2, 1, {{"Z"}, {"value"}, {"B"}, {"objectId", ChannelType::UInt32}});
    for (int x = 0; x < 2; ++x) {
        b->writeFloat("Z")[x] = 1.0f + x;
        b->writeFloat("value")[x] = 10.0f + x;
        b->writeFloat("B")[x] = 0.5f;
        b->writeUInt("objectId")[x] = 7u + x;
    }
    Camera c;
    c.width = 2;
    c.height = 1;
    b->metadata().camera = c;
    return b;
}
}  // namespace

TEST(ChannelSelect, KeepsInTheListedOrderAndRenames) {
    const auto in = image();
    const BufferPtr out = runImage("ChannelSelect", {{"image", {Value(BufferPtr(in))}}, {"channels", {Value(" objectId, value:R ,B")}}});
    EXPECT_EQ(out->channelNames(), (std::vector<std::string>{"objectId", "R", "B"}));
    EXPECT_EQ(out->channelType("objectId"), ChannelType::UInt32);
    EXPECT_EQ(out->hostUInt("objectId")[1], 8u);
    EXPECT_EQ(out->hostFloat("R")[1], 11.0f);
    EXPECT_EQ(out->metadata(), in->metadata());
}

TEST(ChannelSelect, DropKeepsTheRestInOrder) {
    const BufferPtr out = runImage("ChannelSelect", {{"image", {Value(BufferPtr(image()))}}, {"channels", {Value("value")}},
                                                     {"mode", {Value("drop")}}});
    EXPECT_EQ(out->channelNames(), (std::vector<std::string>{"Z", "B", "objectId"}));
    EXPECT_EQ(out->hostFloat("Z")[1], 2.0f);
}

TEST(ChannelSelect, ErrorsListWhatTheImageHas) {
    const BufferPtr in = image();
    const std::string missing = errorOf("ChannelSelect", {{"image", {Value(in)}}, {"channels", {Value("R,G")}}});
    EXPECT_THAT(missing, HasSubstr("'R'"));
    EXPECT_THAT(missing, HasSubstr("Z, value, B, objectId"));
    EXPECT_THAT(errorOf("ChannelSelect", {{"image", {Value(in)}}, {"channels", {Value("Z, value:Z")}}}),
                HasSubstr("twice"));
    EXPECT_THAT(errorOf("ChannelSelect", {{"image", {Value(in)}}, {"channels", {Value(" , ")}}}), HasSubstr("no channel"));
    EXPECT_THAT(errorOf("ChannelSelect", {{"image", {Value(in)}}, {"channels", {Value("value:")}}}), HasSubstr("SOURCE:NEWNAME"));
    EXPECT_THAT(errorOf("ChannelSelect", {{"image", {Value(in)}}, {"channels", {Value("value:R")}}, {"mode", {Value("drop")}}}),
                HasSubstr("cannot rename"));
}
