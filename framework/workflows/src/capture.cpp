#include <darkroom/workflows/capture.h>

#include <darkroom/error.h>

#include <algorithm>
#include <chrono>
#include <sstream>

namespace darkroom::workflows {

namespace {

// What a process says when its cancel flag is set, agreed like an error.
constexpr const char* kCancelled = "darkroom: capture cancelled";

double secondsSince(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The lead opens the database and lists the entries it lacks; every process
// gets the list. A refusal is InputError everywhere.
std::vector<std::size_t> agreeEntriesToRender(const std::vector<CaptureEntry>& entries, ProcessGroup& group,
                                              const CaptureSettings& settings, CinemaWriter*& writer) {
    std::string todo, error;
    if (group.lead()) {
        try {
            writer = &settings.openDatabase();
            for (std::size_t i = 0; i < entries.size(); ++i)
                if (!writer->hasEntry(entries[i].parameters)) todo += std::to_string(i) + " ";
        } catch (const Error& e) {
            error = e.what();
        }
    }
    if (const std::string e = group.agreedError(error); !e.empty()) throw InputError(e);
    group.broadcast(todo);
    std::vector<std::size_t> indices;
    std::istringstream in(todo);
    for (std::size_t i; in >> i;) indices.push_back(i);
    return indices;
}

// The slowest process's render and compositing times.
void slowestTimes(ProcessGroup& group, CaptureSummary& summary) {
    if (group.size() == 1) return;
    std::ostringstream mine;
    mine.precision(17);
    mine << summary.renderSeconds << " " << summary.compositeSeconds;
    for (const std::string& text : group.allGather(mine.str())) {
        std::istringstream in(text);
        double render = 0, composite = 0;
        in >> render >> composite;
        summary.renderSeconds = std::max(summary.renderSeconds, render);
        summary.compositeSeconds = std::max(summary.compositeSeconds, composite);
    }
}

}  // namespace

CaptureSummary captureEntries(const std::vector<CaptureEntry>& entries, const RenderFn& render, ProcessGroup& group,
                              const CaptureSettings& settings) {
    CinemaWriter* writer = nullptr;  // the lead's
    const std::vector<std::size_t> todo = agreeEntriesToRender(entries, group, settings, writer);
    if (settings.entriesAgreed) settings.entriesAgreed();
    CaptureSummary summary;
    summary.kept = entries.size() - todo.size();

    // Over several processes both ids are rendered even when not stored:
    // at equal depth the lower (objectId, primitiveId) wins, in the
    // compositing as inside Embree, so any partition gives the
    // single-process result. They are dropped before writing.
    const bool several = group.size() > 1;
    CaptureRequest request = settings.request;
    if (several) request.objectId = request.primitiveId = true;
    std::string error;
    for (std::size_t k = 0; k < todo.size(); ++k) {
        const CaptureEntry& entry = entries[todo[k]];
        if (group.lead() && settings.progress) settings.progress(double(k) / double(todo.size()), entry.label);
        auto t = std::chrono::steady_clock::now();
        BufferPtr image;
        try {
            if (settings.cancel && settings.cancel->load()) throw Error(kCancelled);
            image = render(entry.camera, request);
        } catch (const Error& e) {
            error = e.what();
        }
        summary.renderSeconds += secondsSince(t);
        // A failure on any process (this render, or the lead's last write)
        // stops all; so does a cancel on any.
        if (const std::string e = group.agreedError(error); !e.empty()) {
            if (e.find(kCancelled) != std::string::npos) throw Cancelled();
            throw Error(e);
        }
        if (several) {
            t = std::chrono::steady_clock::now();
            image = group.compositeByDepth(*image, settings.primitiveOffsets, settings.request.objectId,
                                           settings.request.primitiveId);
            summary.compositeSeconds += secondsSince(t);
        }
        if (!image) continue;  // not the lead
        t = std::chrono::steady_clock::now();
        try {
            writer->addEntry(entry.parameters, *image, settings.attachments);
        } catch (const Error& e) {
            error = e.what();
        }
        summary.writeSeconds += secondsSince(t);
    }
    if (const std::string e = group.agreedError(error); !e.empty()) throw Error(e);
    summary.rendered = todo.size();
    slowestTimes(group, summary);
    return summary;
}

}  // namespace darkroom::workflows
