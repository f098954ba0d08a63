#include "channel_select.h"
#include <darkroom/strings.h>

#include "image_checks.h"

#include <darkroom/error.h>

#include <algorithm>
#include <darkroom/channel_text.h>

namespace darkroom {

namespace {

struct Pick {
    std::string from, to;
};

// "R, G, value:Z" -> {R->R, G->G, value->Z}.
std::vector<Pick> parsePicks(const std::string& text) {
    std::vector<Pick> picks;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const std::string item = std::string(trimBlanks(text.substr(start, comma - start)));
        start = comma + 1;
        if (item.empty()) continue;
        const auto colon = item.find(':');
        Pick p{std::string(trimBlanks(item.substr(0, colon))), colon == std::string::npos ? "" : std::string(trimBlanks(item.substr(colon + 1)))};
        if (colon == std::string::npos) p.to = p.from;
        if (p.from.empty() || p.to.empty())
            throw Error("'" + item + "' in 'channels' is not NAME or SOURCE:NEWNAME");
        picks.push_back(p);
    }
    if (picks.empty()) throw Error("'channels' lists no channel; write e.g. \"R, G, B, A\" or \"value:R\"");
    return picks;
}

}  // namespace

void ChannelSelect::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const std::vector<Pick> picks = parsePicks(ctx.get(channels_));
    const bool keep = ctx.get(mode_) == Mode::Keep;

    for (const Pick& p : picks) {
        if (!in->hasChannel(p.from))
            throw Error("the image has no channel '" + p.from + "'; it has " + channelListText(*in));
        if (!keep && p.to != p.from)
            throw Error("drop mode cannot rename ('" + p.from + ":" + p.to + "'); list plain names");
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
            if (c.name == p.to) throw Error("channel '" + p.to + "' would appear twice in the output");
        channels.push_back({p.to, *in->channelType(p.from)});
    }

    // The chosen planes are shared, under their new names; nothing is copied.
    auto out = ctx.allocate(in->width(), in->height(), {});
    out->metadata() = in->metadata();
    for (std::size_t k = 0; k < chosen.size(); ++k) out->setPlane(channels[k], in->plane(chosen[k].from));
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
