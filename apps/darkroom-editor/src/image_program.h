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
// Needs a current OpenGL context (>= 3.0) for every call.
#include "display.h"

#include <darkroom/buffer.h>

#include <QRectF>
#include <QSize>
#include <QString>

#include <map>
#include <memory>

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
    // panning and zooming do neither).
    int uploads() const { return uploads_; }
    int mappings() const { return mappings_; }

private:
    QOpenGLTexture* channelTexture(const std::string& name);
    void map(const DisplaySpec& spec);
    std::unique_ptr<QOpenGLShaderProgram> mapProgram_, drawProgram_;
    std::unique_ptr<QOpenGLFramebufferObject> mapped_;
    DisplaySpec mappedSpec_;
    bool mappedValid_ = false;
    std::unique_ptr<QOpenGLVertexArrayObject> vao_;
    std::unique_ptr<QOpenGLBuffer> quad_;
    std::unique_ptr<QOpenGLTexture> table_;
    std::map<std::string, std::unique_ptr<QOpenGLTexture>> channels_;
    darkroom::BufferPtr image_;
    int uploads_ = 0;
    int mappings_ = 0;
};

}  // namespace editor
