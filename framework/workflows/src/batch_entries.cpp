#include "batch_entries.h"

#include <darkroom/data/cinema/composable.h>
#include <darkroom/data/cinema/naming.h>

#include <algorithm>
#include <set>
#include <utility>

namespace darkroom::workflows::batch {

namespace {

using Pairs = std::vector<std::pair<std::string, std::string>>;

// The row's parameters that are not the set's own bookkeeping (CIS*).
Pairs ownParameters(const CinemaDatabase& db, std::size_t row) {
    Pairs p;
    for (const std::size_t c : db.parameterColumns()) {
        const std::string& name = db.columns()[c].name;
        if (name.rfind("CIS", 0) != 0) p.emplace_back(name, db.cell(row, c));
    }
    return p;
}

BatchEntries layerEntries(const CinemaDatabase& db, const std::vector<std::size_t>& selected) {
    BatchEntries e;
    std::vector<Pairs> parameters;
    std::vector<std::pair<std::string, std::string>> ids;  // image, layer
    for (const CisImage& image : composableImages(db, selected))
        for (const CisLayer& layer : image.layers) {
            e.rows.push_back(layer.channels.front().row);
            parameters.push_back(ownParameters(db, e.rows.back()));
            ids.emplace_back(image.id, layer.id);
        }
    // The parameters name a layer when they tell every layer apart (one
    // object per layer); otherwise the image and layer ids say which.
    std::set<std::string> seen;
    bool distinct = true;
    for (const Pairs& p : parameters) distinct = distinct && !p.empty() && seen.insert(cinemaEntryName(p)).second;
    for (std::size_t k = 0; k < e.rows.size(); ++k) {
        Pairs p = parameters[k];
        if (!distinct) {
            p.emplace_back("image", ids[k].first);
            p.emplace_back("layer", ids[k].second);
        }
        e.names[e.rows[k]] = cinemaEntryName(p);
    }
    // composableImages groups by first appearance: back into database order.
    std::sort(e.rows.begin(), e.rows.end());
    return e;
}

}  // namespace

BatchEntries batchEntries(const CinemaDatabase& db, const std::vector<std::size_t>& selected) {
    if (isComposableImageSet(db)) return layerEntries(db, selected);
    BatchEntries e;
    e.rows = selected;
    for (const std::size_t r : selected) e.names[r] = db.entryName(r);
    return e;
}

}  // namespace darkroom::workflows::batch
