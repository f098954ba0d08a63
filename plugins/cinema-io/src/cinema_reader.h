#pragma once
#include <darkroom/filter.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <string>

namespace darkroom {

class CinemaDatabase;

// Picks one entry of a Cinema database by parameter values and outputs its
// product as an image (EXR with every channel; PNG/JPEG/TIFF as linear colour).
class CinemaReader : public Filter {
public:
    CinemaReader();
    ~CinemaReader() override;
    PortList ports() const override { return {database_, entry_, parameters_, selection_, file_, strict_, result_, row_}; }
    void execute(Context& ctx) override;

private:
    PathIn database_{"database", "", "The Cinema database: a .cdb folder or its data.csv"};
    IntIn entry_{"entry", -1, -1, std::numeric_limits<std::int64_t>::max(),
                 "Which entry, by its row in data.csv (0 = the first row below the header), as the runner's "
                 "--foreach and the editor's browser give it; -1 = choose by `parameters`"};
    StringIn parameters_{"parameters", "",
                         "Which entry, as column=value pairs: 'phi=30, theta=45' (numbers snap to the "
                         "nearest value present; unnamed columns take any value), or an SQL WHERE "
                         "expression: 'phi > 0 AND theta = 0' (first matching row). Empty = the first row. "
                         "In a composable image set the rows pick one layer ('object=000'), read whole. "
                         "Used when `entry` is -1"};
    StringIn selection_{"selection", "",
                        "The rows a run over this database covers, as --where takes them (darkroom run --foreach "
                        "sets it from its --where): ColorMapping's database range spans them. Empty = every row"};
    StringIn file_{"file", "", "FILE column to read (e.g. FILE2); empty = the first FILE column"};
    BoolIn strict_{"strict", false, "Treat irregular rows in data.csv as errors instead of warnings"};
    ImageOut result_{"image",
                     "The entry's product: every EXR channel; linear R, G, B(, A) for 8-bit images; .npz "
                     "members and .vti point arrays as channels; a composable image set's layer with "
                     "depth as Z and colormap.<channel> attributes"};
    ValueOut row_{"row", PortType::Row,
                  "The entry read: its parameter columns as written, then its FILE columns as absolute paths "
                  "(as text: 'time=0.5, phi=30, FILE=/data/a.cdb/x.exr'); Annotation, CinemaWriter and Spheres "
                  "take it"};

    // The parsed data.csv, kept while the file is unchanged so that moving a
    // parameter slider in the editor does not re-read it.
    struct Cache;
    std::unique_ptr<Cache> cache_;
    std::mutex mutex_;
    std::shared_ptr<const CinemaDatabase> open(const std::string& path, bool strict);
    // The row `parameters` chooses (the first of several, with a warning).
    std::size_t rowOf(const CinemaDatabase& db, const std::string& parameters, Context& ctx) const;
};

}  // namespace darkroom
