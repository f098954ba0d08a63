#pragma once
// What a session captures: image size, projection, cameras and channels.
// Each setter checks its arguments (arguments.h); bounds that depend on the
// scene's size are checked against the data's bounds at every capture
// (checkReach). The setup is fixed once a capture has opened the database,
// and recorded there (origin), so that neither a call in mid-session nor a
// resumed session with another setup mixes products (docs/insitu.md,
// "One database, one setup").
#include <darkroom/camera.h>
#include <darkroom/capture_backend.h>
#include <darkroom/data/cinema/writer.h>
#include <darkroom/scene.h>

#include <string>
#include <utility>
#include <vector>

namespace darkroom::insitu {

// Every camera with its Cinema parameters (phi and theta, or camera).
using CameraList = std::vector<std::pair<std::vector<std::pair<std::string, double>>, Camera>>;

class Setup {
public:
    void setImage(int width, int height, double fovDegrees, double viewHeight);
    void cameraOrbit(const Vec3& target, double distance, const Vec3& up, std::vector<double> phi,
                     std::vector<double> theta);
    void addCamera(const Vec3& position, const Vec3& target, const Vec3& up);
    void requestField(const std::string& name);
    void requestNormals(int on);
    void requestIds(int objectIds, int primitiveIds);
    void setHalfFloat(int on);

    // From now on every setter throws BadInput (the database holds this setup).
    void fix() { fixed_ = true; }
    bool fixed() const { return fixed_; }

    bool hasCameras() const { return !specs_.empty(); }
    const CaptureRequest& request() const { return request_; }
    bool halfFloat() const { return half_; }
    // Throws BadInput ("darkroom_insitu_capture: ...") when a camera or the
    // view height is out of proportion to `data`, the bounds of the step's
    // objects on every rank.
    void checkReach(const Bounds& data) const;
    CameraList cameras() const;
    // What the database is made from, for its marker (CinemaWriterOptions::origin).
    std::vector<CinemaOriginItem> origin() const;

private:
    struct CameraSpec {
        bool orbit = false;
        Vec3 target, up, position;
        double distance = 0;
        std::vector<double> phi, theta;
    };
    void refuseIfFixed(const char* call) const;

    int width_ = 512, height_ = 512;
    double fov_ = 30.0, viewHeight_ = 0.0;
    std::vector<CameraSpec> specs_;
    CaptureRequest request_;
    bool half_ = false;
    bool fixed_ = false;
};

}  // namespace darkroom::insitu
