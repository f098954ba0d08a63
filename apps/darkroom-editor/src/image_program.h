#pragma once
// The render view's GPU side: each channel a display mode needs is uploaded
// once per image, as its own single-channel float texture straight from the
// buffer's plane (no interleaving, no conversion; uint32 ids are the one
// exception, converted to float on upload). A first shader pass maps the
// channels to display colour (sRGB encoding, false colour through a
// 256-entry table, depth and vector mappings) into an 8-bit texture of the
// image's size, once per image and mode; every frame then draws that
// texture over a checkerboard, pan and zoom being the quad's placement. A
// frame costs no CPU work per pixel, and on a software rasteriser (Mesa
// llvmpipe) the per-frame shader stays a single texture fetch.
// On llvmpipe the mapping pass costs about 40 ns per pixel (180 ms for a
// 2048 x 2048 image on the 2-core machine), so an image shown smaller than
// its size is mapped at the coarsest power-of-two reduction that still
// covers every screen pixel (every 2nd or 4th pixel of each row and
// column); zooming in past it maps the full image, once. Channel textures
// of an image of the same size as the last one are refilled rather than
// reallocated (half the upload time: no fresh pages to clear).
// Needs a current OpenGL context (>= 3.0) for every call.
#include "display.h"

#include <darkroom/buffer.h>

#include <QRectF>
#include <QSize>
#include <QString>

#include <map>
#include <memory>
#include <vector>

class QOpenGLBuffer;
class QOpenGLFramebufferObject;
class QOpenGLShaderProgram;
class QOpenGLTexture;
class QOpenGLVertexArrayObject;

namespace editor {

class ImageProgram {
public:
    ImageProgram();
    ~ImageProgram();
    // Compiles the shader; false (and `error`) when the context cannot.
    bool initialize(QString* error);
    // Drops the textures of the previous image.
    void setImage(darkroom::BufferPtr image);
    // Draws `spec` of the image into `target` (widget pixels, top-left
    // origin) of a viewport of `viewport` pixels, into framebuffer `fbo`;
    // `smooth` filters when magnified (previews), else magnified pixels
    // stay square.
    void draw(const DisplaySpec& spec, QRectF target, QSize viewport, unsigned fbo, bool smooth);
    // Channel textures uploaded and mapping passes run so far (tests:
    // panning and zooming do neither, once the full image is mapped).
    int uploads() const { return uploads_; }
    int mappings() const { return mappings_; }
    // The reduction of the last mapping: the mapped texture holds every
    // 2^level-th pixel of each row and column.
    int mappedLevel() const { return mappedLevel_; }

private:
    QOpenGLTexture* channelTexture(const std::string& name);
    void map(const DisplaySpec& spec, int level);
    int levelFor(QRectF target) const;  // of the mapping, for drawing into `target`
    std::unique_ptr<QOpenGLShaderProgram> mapProgram_, drawProgram_;
    std::unique_ptr<QOpenGLFramebufferObject> mapped_;
    DisplaySpec mappedSpec_;
    bool mappedValid_ = false;
    int mappedLevel_ = 0;
    std::unique_ptr<QOpenGLVertexArrayObject> vao_;
    std::unique_ptr<QOpenGLBuffer> quad_;
    std::unique_ptr<QOpenGLTexture> table_;
    std::map<std::string, std::unique_ptr<QOpenGLTexture>> channels_;
    std::vector<std::unique_ptr<QOpenGLTexture>> spare_;  // of the last image's size, to refill
    darkroom::BufferPtr image_;
    int uploads_ = 0;
    int mappings_ = 0;
};

}  // namespace editor
