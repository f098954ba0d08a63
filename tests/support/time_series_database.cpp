#include "time_series_database.h"

#include "test_support.h"

#include <darkroom/data/cinema/writer.h>

namespace darkroom::test {

void writeTimeSeriesDatabase(const std::string& path, const std::vector<double>& times) {
    CinemaWriter w(path, {"time"});
    for (const double t : times)
        w.addEntry({{"time", CinemaValue(t)}},
                   *makeImage(6, 4, {"Z", "value"}, [=](int, int, int) { return float(t); }));
    w.finish();
}

}  // namespace darkroom::test
