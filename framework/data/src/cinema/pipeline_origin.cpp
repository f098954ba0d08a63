#include <darkroom/data/cinema/pipeline_origin.h>

#include <darkroom/error.h>

#include <map>

namespace darkroom {

const char* const kUpstreamPipelineSource = "the pipeline upstream of the writer";

std::vector<CinemaOriginItem> pipelineOriginItems(const std::string& text) {
    std::vector<CinemaOriginItem> out;
    std::size_t start = 0, number = 1;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(start, end - start);
        if (!line.empty()) {
            const std::size_t tab = line.find('\t');
            if (tab == std::string::npos)
                throw InputError("pipeline, line " + std::to_string(number) + ": expected 'node<TAB>digest', got '" +
                                 line + "'");
            out.push_back({kUpstreamPipelineSource, line.substr(0, tab), line.substr(tab + 1), false});
        }
        start = end + 1;
        ++number;
    }
    return out;
}

std::string describePipelineChange(const std::vector<CinemaOriginItem>& recorded,
                                   const std::vector<CinemaOriginItem>& now) {
    std::map<std::string, std::string> before;
    for (const auto& item : recorded)
        if (item.source == kUpstreamPipelineSource) before[item.key] = item.value;
    bool described = false;
    for (const auto& item : now) described = described || item.source == kUpstreamPipelineSource;
    if (before.empty() && described)
        return "the database records no pipeline (written by an earlier version, or not through the runner)";
    std::string out;
    const auto add = [&out](const std::string& what) { out += (out.empty() ? "" : ", ") + what; };
    for (const auto& item : now) {
        if (item.source != kUpstreamPipelineSource) continue;
        const auto it = before.find(item.key);
        if (it == before.end()) add(item.key + " added");
        else if (it->second != item.value) add(item.key + " changed");
        if (it != before.end()) before.erase(it);
    }
    for (const auto& [key, value] : before) add(key + " removed");
    return out;
}

}  // namespace darkroom
