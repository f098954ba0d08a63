#include "channel_select.h"

#include "image_checks.h"

#include <darkroom/error.h>

#include <algorithm>

namespace darkroom {

namespace {

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

struct Pick {
    std::string from, to;
};

// "R, G, value:Z" -> {R->R, G->G, value->Z}.
std::vector<Pick> parsePicks(const std::string& text, const std::string& node) {
    std::vector<Pick> picks;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const std::string item = trim(text.substr(start, comma - start));
        start = comma + 1;
        if (item.empty()) continue;
        const auto colon = item.find(':');
        Pick p{trim(item.substr(0, colon)), colon == std::string::npos ? "" : trim(item.substr(colon + 1))};
        if (colon == std::string::npos) p.to = p.from;
        if (p.from.empty() || p.to.empty())
            throw Error(node + ": '" + item + "' in 'channels' is not NAME or SOURCE:NEWNAME");
        picks.push_back(p);
    }
    if (picks.empty()) throw Error(node + ": 'channels' lists no channel; write e.g. \"R, G, B, A\" or \"value:R\"");
    return picks;
}

}  // namespace

PortList ChannelSelect::ports() const {
    PortList p;
    p.imageIn("image", "Any image");
    p.stringIn("channels", "R, G, B, A",
               "Comma-separated channel names; in keep mode SOURCE:NEWNAME renames (e.g. \"value:R\")");
    p.enumIn("mode", {"keep", "drop"}, "keep",
             "keep: output only the listed channels, in the listed order; drop: output all others, in their order");
    p.imageOut("image", "The selected channels with the input's metadata (camera)");
    return p;
}

void ChannelSelect::execute(Context& ctx) {
    const std::string node = "ChannelSelect '" + ctx.nodeName() + "'";
    const BufferPtr in = ctx.requireImage("image");
    const std::vector<Pick> picks = parsePicks(ctx.getString("channels"), node);
    const bool keep = ctx.getString("mode") == "keep";

    for (const Pick& p : picks) {
        if (!in->hasChannel(p.from))
            throw Error(node + ": the image has no channel '" + p.from + "'; it has " + utils::channelList(*in));
        if (!keep && p.to != p.from)
            throw Error(node + ": drop mode cannot rename ('" + p.from + ":" + p.to + "'); list plain names");
    }

    std::vector<Pick> chosen;
    if (keep) {
        chosen = picks;
    } else {
        for (const auto& c : in->channels())
            if (std::none_of(picks.begin(), picks.end(), [&](const Pick& p) { return p.from == c.name; }))
                chosen.push_back({c.name, c.name});
    }
    std::vector<ChannelDesc> channels;
    for (const Pick& p : chosen) {
        for (const auto& c : channels)
            if (c.name == p.to) throw Error(node + ": channel '" + p.to + "' would appear twice in the output");
        channels.push_back({p.to, *in->channelType(p.from)});
    }

    auto out = ctx.allocate(in->width(), in->height(), channels);
    out->metadata() = in->metadata();
    const std::size_t n = in->pixelCount();
    for (std::size_t k = 0; k < chosen.size(); ++k) {
        if (channels[k].type == ChannelType::Float32)
            std::copy_n(in->hostFloat(chosen[k].from), n, out->hostFloat(channels[k].name));
        else
            std::copy_n(in->hostUInt(chosen[k].from), n, out->hostUInt(channels[k].name));
    }
    ctx.progress(1.0);
    ctx.setOutput("image", BufferPtr(std::move(out)));
}

}  // namespace darkroom
