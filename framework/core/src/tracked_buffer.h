#pragma once
// An input buffer as a filter sees it: every call that reads pixels, the
// channel list or the metadata is recorded, so the host can key the node's
// cache on exactly what it read (a colour-map edit upstream of SSAO does not
// re-run SSAO, whose AO depends only on Z and the camera). Size is always
// part of the key, so width()/height() are not recorded.
#include <darkroom/buffer.h>

#include <map>
#include <mutex>
#include <string>

namespace darkroom {

struct ReadLog {
    mutable std::mutex mutex;
    bool channelList = false;
    bool metadata = false;
    std::map<std::string, bool, std::less<>> channels;  // names whose pixels (or plane) were asked for

    void channel(std::string_view name) {
        std::lock_guard<std::mutex> lock(mutex);
        channels.emplace(std::string(name), true);
    }
};

class TrackedBuffer final : public Buffer {
public:
    TrackedBuffer(BufferPtr inner, std::string port, int index, ReadLog& log)
        : inner_(std::move(inner)), port_(std::move(port)), index_(index), log_(&log) {}

    // The buffer behind a tracked one (or `b` itself).
    static const BufferPtr& unwrap(const BufferPtr& b);
    // (port, index) of a tracked buffer; false for any other buffer.
    static bool origin(const Buffer* b, std::string& port, int& index);

    const BufferPtr& inner() const { return inner_; }

    int width() const override { return inner_->width(); }
    int height() const override { return inner_->height(); }
    const std::vector<ChannelDesc>& channels() const override {
        std::lock_guard<std::mutex> lock(log_->mutex);
        log_->channelList = true;
        return inner_->channels();
    }
    const BufferMetadata& metadata() const override {
        std::lock_guard<std::mutex> lock(log_->mutex);
        log_->metadata = true;
        return inner_->metadata();
    }
    const float* hostFloat(std::string_view c) const override {
        log_->channel(c);
        return inner_->hostFloat(c);
    }
    const std::uint32_t* hostUInt(std::string_view c) const override {
        log_->channel(c);
        return inner_->hostUInt(c);
    }
    PlanePtr plane(std::string_view c) const override {
        log_->channel(c);
        return inner_->plane(c);
    }

private:
    BufferPtr inner_;
    std::string port_;
    int index_;
    ReadLog* log_;
};

}  // namespace darkroom
