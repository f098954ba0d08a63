#pragma once
// One in situ session: the C API (c_api.cpp) is a thin error boundary over
// this class. See darkroom/insitu.h for what each step means.
#include "ranks.h"

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
struct ObjectView;
}  // namespace embree
}  // namespace darkroom

namespace darkroom::insitu {

// A mistake in the arguments of a call (DARKROOM_INSITU_BAD_INPUT).
class BadInput : public Error {
public:
    using Error::Error;
};

class Session {
public:
    Session(std::string database, int mode);
    ~Session();

    void setRanks(std::unique_ptr<Ranks> ranks);
    void setThreads(int threads);
    void setImage(int width, int height, double fovDegrees, double viewHeight);
    void cameraOrbit(const Vec3& target, double distance, const Vec3& up, std::vector<double> phi,
                     std::vector<double> theta);
    void addCamera(const Vec3& position, const Vec3& target, const Vec3& up);
    void requestField(const std::string& name);
    void requestNormals(bool on) { request_.normals = on; }
    void requestIds(bool objectIds, bool primitiveIds) {
        request_.objectId = objectIds;
        request_.primitiveId = primitiveIds;
    }
    void setHalfFloat(bool on) { half_ = on; }

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
    struct CameraSpec;
    struct StepObject;
    StepObject& declare(const std::string& name, Representation representation);
    // Lines and points: declared with their x, y, z, radius records.
    StepObject& declareRound(const std::string& name, Representation representation, const float* vertices,
                             std::size_t stride, std::int64_t vertexCount, const float* radii, float radius);
    const float* roundVertices(StepObject& o, const float* vertices, std::size_t stride, std::int64_t count,
                               const float* radii, float radius);
    std::vector<std::pair<std::vector<std::pair<std::string, double>>, Camera>> cameras() const;
    void openWriter(const std::vector<std::string>& columns);

    std::string database_;
    int mode_;
    std::unique_ptr<Ranks> ranks_;
    int threads_ = 0;
    bool half_ = false;
    int width_ = 512, height_ = 512;
    double fov_ = 30.0, viewHeight_ = 0.0;
    std::vector<CameraSpec> cameraSpecs_;
    CaptureRequest request_;
    std::unique_ptr<Step> step_;
    std::shared_ptr<embree::Device> device_;
    std::unique_ptr<Context> context_;
    std::unique_ptr<CinemaWriter> writer_;
    bool closed_ = false;
    std::int64_t copied_ = 0, rows_ = 0;
};

}  // namespace darkroom::insitu
