#include "split_objects.h"

#include <algorithm>

namespace darkroom::partition {

std::size_t cellCountOf(const SceneObject& o) {
    std::size_t cells = 0;
    bool anyCellField = false;
    for (const auto& f : o.fields)
        if (f.association == ScalarField::Association::Cell) {
            cells = std::max(cells, f.values.size());
            anyCellField = true;
        }
    if (anyCellField) return cells;
    if (o.primitiveCell.empty()) return o.primitiveCount();
    for (auto c : o.primitiveCell) cells = std::max<std::size_t>(cells, std::size_t(c) + 1);
    return cells;
}

std::pair<std::size_t, std::size_t> shareOf(const SceneObject& o, int rank, int size) {
    const std::size_t n = o.primitiveCount();
    auto ideal = [&](int r) { return std::size_t((unsigned long long)(n) * unsigned(r) / unsigned(size)); };
    if (o.representation != Representation::Lines) return {ideal(rank), ideal(rank + 1)};
    // Move each ideal cut forward to the next segment that does not continue
    // the one before it (Embree joins segments i, i+1 when index[i+1] ==
    // index[i] + 1 and caps the ends otherwise).
    auto cut = [&](std::size_t at) {
        while (at > 0 && at < n && o.indices[at] == o.indices[at - 1] + 1) ++at;
        return at;
    };
    return {cut(ideal(rank)), cut(ideal(rank + 1))};
}

SceneObject shareObject(const SceneObject& o, std::size_t first, std::size_t last) {
    SceneObject s;
    s.name = o.name;
    s.representation = o.representation;
    const bool cellFields = std::any_of(o.fields.begin(), o.fields.end(), [](const ScalarField& f) {
        return f.association == ScalarField::Association::Cell;
    });
    // Cell fields stay whole; the share reaches them through global cell numbers.
    if (!o.primitiveCell.empty())
        s.primitiveCell.assign(o.primitiveCell.begin() + std::ptrdiff_t(first), o.primitiveCell.begin() + std::ptrdiff_t(last));
    else if (cellFields)
        for (std::size_t i = first; i < last; ++i) s.primitiveCell.push_back(std::uint32_t(i));
    switch (o.representation) {
        case Representation::Surface:
        case Representation::Lines: {
            const std::size_t k = o.representation == Representation::Surface ? 3 : 1;
            s.vertices = o.vertices;
            s.indices.assign(o.indices.begin() + std::ptrdiff_t(k * first), o.indices.begin() + std::ptrdiff_t(k * last));
            s.fields = o.fields;
            break;
        }
        case Representation::Points: {
            s.vertices.assign(o.vertices.begin() + std::ptrdiff_t(4 * first), o.vertices.begin() + std::ptrdiff_t(4 * last));
            for (const auto& f : o.fields) {
                ScalarField g{f.name, f.association, {}};
                if (f.association == ScalarField::Association::Point)
                    g.values.assign(f.values.begin() + std::ptrdiff_t(first), f.values.begin() + std::ptrdiff_t(last));
                else
                    g.values = f.values;
                s.fields.push_back(std::move(g));
            }
            break;
        }
    }
    return s;
}

}  // namespace darkroom::partition
