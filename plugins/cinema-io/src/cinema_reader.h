#pragma once
#include <darkroom/filter.h>

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
    PortList ports() const override;
    void execute(Context& ctx) override;

private:
    // The parsed data.csv, kept while the file is unchanged so that moving a
    // parameter slider in the editor does not re-read it.
    struct Cache;
    std::unique_ptr<Cache> cache_;
    std::mutex mutex_;
    std::shared_ptr<const CinemaDatabase> open(const std::string& path, bool strict);
};

}  // namespace darkroom
