#pragma once
// One in situ session: the C API (c_api.cpp) is a thin error boundary over
// this class. See darkroom/insitu.h for what each step means.
#include "arguments.h"
#include "ranks.h"
#include "session_setup.h"

#include <darkroom/capture_backend.h>
#include <darkroom/error.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace darkroom {
class CinemaWriter;
class Context;
namespace embree {
class Device;
class SceneBvh;
struct ObjectView;
}  // namespace embree
}  // namespace darkroom

namespace darkroom::insitu {

class Session {
public:
    Session(std::string database, int mode);
    ~Session();

    void setRanks(std::unique_ptr<ProcessGroup> ranks);
    void setThreads(int threads);
    // Image, cameras and channels (checked there; fixed after the first capture).
    Setup& setup() { return setup_; }

    void beginStep(double time);
    void triangles(const std::string& name, const float* vertices, std::size_t stride, std::int64_t vertexCount,
                   const std::uint32_t* triangles, std::int64_t triangleCount);
    void lines(const std::string& name, const float* vertices, std::size_t stride, std::int64_t vertexCount,
               const std::uint32_t* segments, std::int64_t segmentCount, const float* radii, float radius);
    void points(const std::string& name, const float* vertices, std::size_t stride, std::int64_t vertexCount,
                const float* radii, float radius);
    void field(const std::string& object, const std::string& name, const float* values, std::int64_t count,
               int association);

    void capture();
    void close();

    std::int64_t copiedBytes() const { return copied_; }
    std::int64_t rowsWritten() const { return rows_; }

private:
    struct Step;
    struct StepObject;
    StepObject& declare(const char* call, const std::string& name, Representation representation);
    // Lines and points: declared with their x, y, z, radius records.
    StepObject& declareRound(const char* call, const std::string& name, Representation representation,
                             const float* vertices, std::size_t stride, std::int64_t vertexCount, const float* radii,
                             float radius);
    const float* roundVertices(const char* call, StepObject& o, const float* vertices, std::size_t stride,
                               std::int64_t count, const float* radii, float radius);
    void openWriter(const std::vector<std::string>& columns);
    // This rank's objects ray traceable; every rank declared the same
    // objects (collective).
    std::unique_ptr<embree::SceneBvh> buildThisRanksPart(const std::vector<embree::ObjectView>& views);

    std::string database_;
    int mode_;
    std::unique_ptr<ProcessGroup> ranks_;
    int threads_ = 0;
    Setup setup_;
    std::unique_ptr<Step> step_;
    std::shared_ptr<embree::Device> device_;
    std::unique_ptr<Context> context_;
    std::unique_ptr<CinemaWriter> writer_;
    bool closed_ = false;
    std::int64_t copied_ = 0, rows_ = 0;
};

}  // namespace darkroom::insitu
