#include "image_program.h"

#include <QOpenGLBuffer>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QOpenGLPixelTransferOptions>
#include <QOpenGLShaderProgram>
#include <QOpenGLTexture>
#include <QOpenGLVertexArrayObject>

#include <algorithm>
#include <vector>

namespace editor {
namespace {

// GLSL 1.30 (OpenGL 3.0) in compatibility contexts, 3.30 in core ones: the
// same source either way.
const char* kVertex = R"(
in vec2 corner;            // (0,0) .. (1,1); uv (0,0) is the image's first row
uniform vec4 rect;         // where corner (0,0) and (1,1) land, normalised device coordinates
out vec2 uv;
void main() {
    uv = corner;
    gl_Position = vec4(mix(rect.x, rect.z, corner.x), mix(rect.y, rect.w, corner.y), 0.0, 1.0);
}
)";

// Channels -> display colour with straight alpha, one fragment per image pixel.
const char* kMap = R"(
in vec2 uv;
out vec4 colour;
uniform sampler2D c0, c1, c2, alpha;
uniform sampler2D table;   // 256 x 1, sRGB-encoded false colour
uniform int kind;          // 0 colour, 1 vector, 2 scalar
uniform bool hasAlpha, invert, grey;
uniform float low, high;

float encode(float v) {    // linear -> sRGB (IEC 61966-2-1), clamped to [0, 1]
    if (!(v > 0.0)) return 0.0;
    v = min(v, 1.0);
    return v <= 0.0031308 ? v * 12.92 : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}
bool finite(float v) { return !isnan(v) && !isinf(v); }

void main() {
    if (kind == 0) {
        colour = vec4(encode(texture(c0, uv).r), encode(texture(c1, uv).r), encode(texture(c2, uv).r),
                      hasAlpha ? clamp(texture(alpha, uv).r, 0.0, 1.0) : 1.0);
    } else if (kind == 1) {
        vec3 v = vec3(texture(c0, uv).r, texture(c1, uv).r, texture(c2, uv).r);
        colour = vec4(clamp(0.5 + 0.5 * v, 0.0, 1.0), finite(v.x) ? 1.0 : 0.0);
    } else {
        float v = texture(c0, uv).r;
        if (!finite(v)) {
            colour = vec4(0.0);  // background (infinite depth, NaN): the checkerboard shows
        } else {
            float t = clamp((v - low) / (high - low), 0.0, 1.0);
            if (invert) t = 1.0 - t;  // near is bright
            colour = grey ? vec4(vec3(t), 1.0)
                          : vec4(texelFetch(table, ivec2(int(floor(t * 255.0 + 0.5)), 0), 0).rgb, 1.0);
        }
    }
}
)";

// The mapped image over an 8-pixel checkerboard, one fragment per screen pixel.
const char* kDraw = R"(
in vec2 uv;
out vec4 colour;
uniform sampler2D mapped;
void main() {
    ivec2 cell = ivec2(gl_FragCoord.xy) / 8;
    vec3 under = ((cell.x + cell.y) % 2 == 0) ? vec3(150.0 / 255.0) : vec3(100.0 / 255.0);
    vec4 c = texture(mapped, uv);
    colour = vec4(mix(under, c.rgb, c.a), 1.0);
}
)";

}  // namespace

ImageProgram::ImageProgram() = default;

ImageProgram::~ImageProgram() = default;  // the owner makes its context current first

bool ImageProgram::initialize(QString* error) {
    QOpenGLContext* ctx = QOpenGLContext::currentContext();
    const QSurfaceFormat f = ctx->format();
    if (f.majorVersion() < 3) {
        if (error) *error = QStringLiteral("OpenGL 3.0 or later is needed; this context is %1.%2")
                                .arg(f.majorVersion()).arg(f.minorVersion());
        return false;
    }
    const QByteArray version = f.profile() == QSurfaceFormat::CoreProfile ? "#version 330 core\n" : "#version 130\n";
    auto build = [&](const char* fragment) -> std::unique_ptr<QOpenGLShaderProgram> {
        auto p = std::make_unique<QOpenGLShaderProgram>();
        if (!p->addShaderFromSourceCode(QOpenGLShader::Vertex, version + kVertex) ||
            !p->addShaderFromSourceCode(QOpenGLShader::Fragment, version + fragment)) {
            if (error) *error = p->log();
            return nullptr;
        }
        p->bindAttributeLocation("corner", 0);
        if (!p->link()) {
            if (error) *error = p->log();
            return nullptr;
        }
        return p;
    };
    mapProgram_ = build(kMap);
    drawProgram_ = build(kDraw);
    if (!mapProgram_ || !drawProgram_) return false;

    vao_ = std::make_unique<QOpenGLVertexArrayObject>();
    vao_->create();
    vao_->bind();
    quad_ = std::make_unique<QOpenGLBuffer>(QOpenGLBuffer::VertexBuffer);
    quad_->create();
    quad_->bind();
    const float corners[] = {0, 0, 1, 0, 0, 1, 1, 1};
    quad_->allocate(corners, sizeof(corners));
    auto* gl = ctx->functions();
    gl->glEnableVertexAttribArray(0);  // "corner" in both programs
    gl->glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    vao_->release();

    table_ = std::make_unique<QOpenGLTexture>(QOpenGLTexture::Target2D);
    table_->setFormat(QOpenGLTexture::RGBA8_UNorm);
    table_->setSize(256, 1);
    table_->setMipLevels(1);
    table_->allocateStorage(QOpenGLTexture::RGBA, QOpenGLTexture::UInt8);
    table_->setData(QOpenGLTexture::RGBA, QOpenGLTexture::UInt8, falseColourTable().data());
    table_->setMinMagFilters(QOpenGLTexture::Nearest, QOpenGLTexture::Nearest);
    return true;
}

void ImageProgram::setImage(darkroom::BufferPtr image) {
    // The textures of an image of the same size are refilled by the next one
    // (successive frames of an edit almost always are).
    const bool sameSize = image && image_ && image->width() == image_->width() && image->height() == image_->height();
    if (!sameSize) spare_.clear();
    for (auto& [name, tex] : channels_)
        if (sameSize) spare_.push_back(std::move(tex));
    channels_.clear();
    mappedValid_ = false;
    if (!image) mapped_.reset();
    image_ = std::move(image);
}

int ImageProgram::levelFor(QRectF target) const {
    // The coarsest reduction whose texels are still no larger than a screen
    // pixel: drawing it minifies (or copies), never magnifies.
    constexpr int kMaxLevel = 4;
    const double screenPerPixel =
        std::min(target.width() / image_->width(), target.height() / image_->height());
    int level = 0;
    while (level < kMaxLevel && screenPerPixel * double(2 << level) <= 1.0) ++level;
    return level;
}

QOpenGLTexture* ImageProgram::channelTexture(const std::string& name) {
    auto& tex = channels_[name];
    if (tex) return tex.get();
    if (!spare_.empty()) {
        tex = std::move(spare_.back());
        spare_.pop_back();
    } else {
        tex = std::make_unique<QOpenGLTexture>(QOpenGLTexture::Target2D);
        tex->setFormat(QOpenGLTexture::R32F);
        tex->setSize(image_->width(), image_->height());
        tex->setMipLevels(1);
        tex->allocateStorage(QOpenGLTexture::Red, QOpenGLTexture::Float32);
        tex->setWrapMode(QOpenGLTexture::ClampToEdge);
        // One texel per image pixel in the mapping pass.
        tex->setMinMagFilters(QOpenGLTexture::Nearest, QOpenGLTexture::Nearest);
    }
    QOpenGLPixelTransferOptions rows;
    rows.setAlignment(4);
    if (const float* f = image_->hostFloat(name)) {
        tex->setData(QOpenGLTexture::Red, QOpenGLTexture::Float32, f, &rows);
    } else if (const std::uint32_t* u = image_->hostUInt(name)) {
        std::vector<float> v(u, u + image_->pixelCount());  // ids: shown, never computed with
        tex->setData(QOpenGLTexture::Red, QOpenGLTexture::Float32, v.data(), &rows);
    }
    ++uploads_;
    return tex.get();
}

void ImageProgram::map(const DisplaySpec& spec, int level) {
    // Each texel samples the pixel nearest its centre (nearest filtering):
    // every 2^level-th pixel of each row and column.
    const int w = (image_->width() + (1 << level) - 1) >> level, h = (image_->height() + (1 << level) - 1) >> level;
    if (!mapped_ || mapped_->size() != QSize(w, h)) {
        mapped_ = std::make_unique<QOpenGLFramebufferObject>(w, h, QOpenGLFramebufferObject::NoAttachment,
                                                             GL_TEXTURE_2D, GL_RGBA8);
    }
    QOpenGLTexture* tex[4] = {};
    for (std::size_t i = 0; i < spec.channels.size() && i < 3; ++i) tex[i] = channelTexture(spec.channels[i]);
    for (int i = 1; i < 3; ++i)
        if (!tex[i]) tex[i] = tex[0];
    tex[3] = spec.alpha.empty() ? tex[0] : channelTexture(spec.alpha);

    auto* gl = QOpenGLContext::currentContext()->functions();
    mapped_->bind();
    gl->glViewport(0, 0, w, h);
    mapProgram_->bind();
    for (int i = 0; i < 4; ++i) tex[i]->bind(GLuint(i));
    table_->bind(4);
    mapProgram_->setUniformValue("c0", 0);
    mapProgram_->setUniformValue("c1", 1);
    mapProgram_->setUniformValue("c2", 2);
    mapProgram_->setUniformValue("alpha", 3);
    mapProgram_->setUniformValue("table", 4);
    // Image row 0 into framebuffer row 0 (texture t = 0), read back alike.
    mapProgram_->setUniformValue("rect", -1.0f, -1.0f, 1.0f, 1.0f);
    mapProgram_->setUniformValue("kind", spec.kind == DisplaySpec::Kind::Colour ? 0 : spec.kind == DisplaySpec::Kind::Vector ? 1 : 2);
    mapProgram_->setUniformValue("hasAlpha", int(!spec.alpha.empty()));
    mapProgram_->setUniformValue("invert", int(spec.invert));
    mapProgram_->setUniformValue("grey", int(spec.grey));
    mapProgram_->setUniformValue("low", spec.low);
    mapProgram_->setUniformValue("high", spec.high);
    vao_->bind();
    gl->glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    vao_->release();
    mapProgram_->release();
    mapped_->release();
    mappedSpec_ = spec;
    mappedValid_ = true;
    mappedLevel_ = level;
    ++mappings_;
}

void ImageProgram::draw(const DisplaySpec& spec, QRectF target, QSize viewport, unsigned fbo, bool smooth) {
    if (!drawProgram_ || !image_ || spec.kind == DisplaySpec::Kind::None || image_->width() <= 0) return;
    const int level = levelFor(target);
    if (!mappedValid_ || !(mappedSpec_ == spec)) map(spec, level);
    else if (level < mappedLevel_) map(spec, 0);  // zoomed in past the reduction: all pixels, once

    auto* gl = QOpenGLContext::currentContext()->functions();
    gl->glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl->glViewport(0, 0, viewport.width(), viewport.height());
    gl->glActiveTexture(GL_TEXTURE0);
    gl->glBindTexture(GL_TEXTURE_2D, mapped_->texture());
    // Square pixels when magnified, so single pixels can be probed; previews
    // are filtered: they stand for the picture, not for its pixels.
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, smooth ? GL_LINEAR : GL_NEAREST);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    const auto ndcX = [&](double x) { return float(2.0 * x / viewport.width() - 1.0); };
    const auto ndcY = [&](double y) { return float(1.0 - 2.0 * y / viewport.height()); };
    drawProgram_->bind();
    drawProgram_->setUniformValue("mapped", 0);
    drawProgram_->setUniformValue("rect", ndcX(target.left()), ndcY(target.top()), ndcX(target.right()),
                                  ndcY(target.bottom()));
    vao_->bind();
    gl->glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    vao_->release();
    drawProgram_->release();
    gl->glBindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace editor
