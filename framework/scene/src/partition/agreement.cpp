#include "agreement.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cstring>
#include <map>

namespace darkroom::partition {

namespace {

constexpr char kPartSeparator = '\x1e';
constexpr char kFieldSeparator = '\x1f';

std::string describeParts(const std::vector<SceneObject>& parts) {
    std::string s;
    for (const auto& p : parts) {
        s += char('0' + int(p.representation));
        for (const auto& f : p.fields)
            s += kFieldSeparator + f.name + (f.association == ScalarField::Association::Cell ? "#c" : "#p");
        s += kPartSeparator;
    }
    return s;
}

std::vector<std::string> split(const std::string& s, char separator) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= s.size(); ++i)
        if (i == s.size() || s[i] == separator) {
            if (i > start) out.push_back(s.substr(start, i - start));
            start = i + 1;
        }
    return out;
}

std::string readable(const std::string& fields) {
    std::string s;
    for (const auto& f : split(fields, kFieldSeparator))
        s += (s.empty() ? "" : ", ") + f.substr(0, f.size() - 2) + (f.back() == 'c' ? " (cell)" : "");
    return s.empty() ? "none" : s;
}

void throwFirstError(const std::vector<std::string>& all) {
    for (std::size_t r = 0; r < all.size(); ++r)
        if (!all[r].empty() && all[r][0] == 'E')
            throw Error(all.size() > 1 ? "rank " + std::to_string(r) + ": " + all[r].substr(1) : all[r].substr(1));
}

}  // namespace

void agreeNoError(const std::string& error, ProcessGroup& group) {
    throwFirstError(group.allGather(error.empty() ? std::string("P") : "E" + error));
}

std::vector<SceneObject> agreeParts(std::vector<SceneObject> local, ProcessGroup* group, const std::string& error,
                                    const std::string& source) {
    std::vector<std::string> all;
    if (group) all = group->allGather(error.empty() ? "P" + describeParts(local) : "E" + error);
    else all = {error.empty() ? "P" + describeParts(local) : "E" + error};
    throwFirstError(all);

    // Representation -> its fields as the first process that has it reports them.
    std::map<int, std::pair<std::string, std::size_t>> agreed;
    for (std::size_t r = 0; r < all.size(); ++r)
        for (const auto& part : split(all[r].substr(1), kPartSeparator)) {
            const int rep = part[0] - '0';
            const std::string fields = part.substr(1);
            auto [it, fresh] = agreed.emplace(rep, std::make_pair(fields, r));
            if (!fresh && it->second.first != fields)
                throw Error(source + ": the pieces of rank " + std::to_string(it->second.second) + " carry the " +
                            toString(Representation(rep)) + " fields " + readable(it->second.first) +
                            " but those of rank " + std::to_string(r) + " carry " + readable(fields) +
                            "; the pieces of one parallel file must carry the same arrays");
        }
    std::vector<SceneObject> out;
    for (const auto& [rep, fields] : agreed) {
        auto mine = std::find_if(local.begin(), local.end(),
                                 // Captured by value: clang before 16 cannot capture a structured binding.
                                 [r = rep](const SceneObject& o) { return int(o.representation) == r; });
        if (mine != local.end()) {
            out.push_back(std::move(*mine));
            continue;
        }
        SceneObject empty;
        empty.representation = Representation(rep);
        for (const auto& f : split(fields.first, kFieldSeparator))
            empty.fields.push_back({f.substr(0, f.size() - 2),
                                    f.back() == 'c' ? ScalarField::Association::Cell : ScalarField::Association::Point,
                                    {}});
        out.push_back(std::move(empty));
    }
    if (out.empty()) throw Error(source + ": the pieces hold no geometry");
    return out;
}

Bounds agreeBounds(const Bounds& local, ProcessGroup& group) {
    double mine[6] = {local.lo.x, local.lo.y, local.lo.z, local.hi.x, local.hi.y, local.hi.z};
    const auto all = group.allGather(std::string(reinterpret_cast<const char*>(mine), sizeof mine));
    Bounds b;
    for (const auto& s : all) {
        double v[6];
        if (s.size() != sizeof v) throw Error("scene partition: a process sent malformed bounds");
        std::memcpy(v, s.data(), sizeof v);
        b.lo = {std::min(b.lo.x, v[0]), std::min(b.lo.y, v[1]), std::min(b.lo.z, v[2])};
        b.hi = {std::max(b.hi.x, v[3]), std::max(b.hi.y, v[4]), std::max(b.hi.z, v[5])};
    }
    return b;
}

std::vector<std::uint64_t> exclusiveSums(const std::vector<std::uint64_t>& counts, ProcessGroup& group,
                                         std::vector<std::uint64_t>& totals) {
    const auto all = group.allGather(
        std::string(reinterpret_cast<const char*>(counts.data()), counts.size() * sizeof(std::uint64_t)));
    std::vector<std::uint64_t> before(counts.size(), 0);
    totals.assign(counts.size(), 0);
    for (int r = 0; r < int(all.size()); ++r) {
        if (all[std::size_t(r)].size() != counts.size() * sizeof(std::uint64_t))
            throw Error("scene partition: processes disagree on the number of objects");
        std::vector<std::uint64_t> theirs(counts.size());
        std::memcpy(theirs.data(), all[std::size_t(r)].data(), all[std::size_t(r)].size());
        for (std::size_t i = 0; i < counts.size(); ++i) {
            if (r < group.rank()) before[i] += theirs[i];
            totals[i] += theirs[i];
        }
    }
    return before;
}

}  // namespace darkroom::partition
