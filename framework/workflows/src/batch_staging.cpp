#include "batch_staging.h"

#include "batch_index.h"

#include <darkroom/error.h>

#include <filesystem>
#include <set>
#include <sstream>

namespace darkroom::workflows::batch {

namespace fs = std::filesystem;

std::vector<std::size_t> entriesToShade(const BatchSettings& s, const Plan& p, ProcessGroup& group) {
    std::string todo, refused;
    if (group.lead()) {
        std::vector<std::set<std::string>> keptByDatabase;
        for (const auto& d : p.databases) {
            try {
                prepareDatabase(d, p.staging);
                if (s.resume) keptByDatabase.push_back(entriesKeptByResume(d));
            } catch (const Error& e) {
                refused = label(d) + ": " + e.what();
                break;
            }
        }
        for (std::size_t k = 0; k < p.rows.size() && refused.empty(); ++k) {
            bool done = s.resume && !(p.outputs.empty() && p.databases.empty());
            for (const auto& f : p.filesOf(p.rows[k])) done = done && fs::is_regular_file(f) && fs::file_size(f) > 0;
            for (const auto& entries : keptByDatabase) done = done && entries.count(p.db->entryName(p.rows[k]));
            if (!done) todo += std::to_string(k) + " ";
        }
    }
    if (const std::string e = group.agreedError(refused); !e.empty()) throw InputError(e);
    group.broadcast(todo);
    std::vector<std::size_t> out;
    std::istringstream in(todo);
    for (std::size_t k; in >> k;) out.push_back(k);
    return out;
}

void finishOnLead(const BatchSettings& s, const Plan& p, const std::vector<std::size_t>& todo,
                  const std::vector<std::string>& shadedRecords, std::exception_ptr& failure) {
    const auto keep = [&failure](const std::string& message) {
        if (!failure) failure = std::make_exception_ptr(Error(message));
    };
    for (const auto& d : p.databases) {
        if (!p.staging) break;
        try {
            mergeStagedEntries(d, p.firstLaneInPlace);
        } catch (const Error& e) {
            keep(label(d) + ": " + e.what());
        }
    }
    if (s.index.empty()) return;
    try {
        writeIndexOf(s.index, p, todo, shadedRecords);
    } catch (const Error& e) {
        keep(e.what());
    }
}

}  // namespace darkroom::workflows::batch
