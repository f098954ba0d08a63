#include <darkroom/text/text_drawing.h>

#include <darkroom/text/text_limits.h>

#include <darkroom/context.h>
#include <darkroom/error.h>
#include <darkroom/srgb.h>

#include <cairo.h>
#include <pango/pangocairo.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>

namespace darkroom::text {

namespace {

// fontconfig's first initialisation and pango's per-thread font maps are not
// safe to race; text is cheap next to a pass, so one lock serialises it all.
std::mutex& pangoMutex() {
    static std::mutex m;
    return m;
}

struct LayoutDeleter {
    void operator()(PangoLayout* l) const { g_object_unref(l); }
};
using Layout = std::unique_ptr<PangoLayout, LayoutDeleter>;

// A layout on `cr` with unhinted, greyscale-antialiased glyphs at fractional
// positions, so text scales exactly with its size.
Layout makeLayout(cairo_t* cr, const std::string& text, const Font& font, Align align, bool markup) {
    // The nodes check their text first, naming what made it; this holds for any other caller.
    checkTextLength(text, "text");
    Layout layout(pango_cairo_create_layout(cr));
    PangoContext* context = pango_layout_get_context(layout.get());
    cairo_font_options_t* options = cairo_font_options_create();
    cairo_font_options_set_antialias(options, CAIRO_ANTIALIAS_GRAY);
    cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
    pango_cairo_context_set_font_options(context, options);
    cairo_font_options_destroy(options);
    pango_context_set_round_glyph_positions(context, FALSE);
    pango_layout_context_changed(layout.get());

    PangoFontDescription* desc = pango_font_description_new();
    pango_font_description_set_family(desc, font.family.c_str());
    pango_font_description_set_weight(desc, font.bold ? PANGO_WEIGHT_BOLD : PANGO_WEIGHT_NORMAL);
    pango_font_description_set_absolute_size(desc, std::max(1.0, font.sizePx) * PANGO_SCALE);
    pango_layout_set_font_description(layout.get(), desc);
    pango_font_description_free(desc);
    pango_layout_set_alignment(layout.get(), align == Align::Left     ? PANGO_ALIGN_LEFT
                                             : align == Align::Center ? PANGO_ALIGN_CENTER
                                                                      : PANGO_ALIGN_RIGHT);
    if (markup) {
        GError* error = nullptr;
        if (!pango_parse_markup(text.c_str(), -1, 0, nullptr, nullptr, nullptr, &error)) {
            const std::string why = error ? error->message : "malformed";
            if (error) g_error_free(error);
            throw Error("text '" + text + "' is not valid Pango markup: " + why);
        }
        pango_layout_set_markup(layout.get(), text.c_str(), -1);
    } else {
        pango_layout_set_text(layout.get(), text.c_str(), -1);
    }
    return layout;
}

TextBox boxOf(PangoLayout* layout) {
    PangoRectangle ink, logical;
    pango_layout_get_extents(layout, &ink, &logical);
    TextBox b;
    b.width = double(logical.width) / PANGO_SCALE;
    b.height = double(logical.height) / PANGO_SCALE;
    b.baseline = double(pango_layout_get_baseline(layout)) / PANGO_SCALE;
    return b;
}

}  // namespace

struct Mask::Impl {
    cairo_surface_t* surface = nullptr;
    cairo_t* cr = nullptr;
    int width = 0, height = 0;
};

Mask::Mask(int width, int height) : impl_(std::make_unique<Impl>()) {
    if (width <= 0 || height <= 0 || width > 32767 || height > 32767)
        throw Error("a text mask of " + std::to_string(width) + " x " + std::to_string(height) +
                    " pixels is outside cairo's limits (1 to 32767 per side)");
    std::lock_guard<std::mutex> g(pangoMutex());
    impl_->width = width;
    impl_->height = height;
    impl_->surface = cairo_image_surface_create(CAIRO_FORMAT_A8, width, height);
    impl_->cr = cairo_create(impl_->surface);
    if (cairo_status(impl_->cr) != CAIRO_STATUS_SUCCESS) {
        const std::string why = cairo_status_to_string(cairo_status(impl_->cr));
        cairo_destroy(impl_->cr);
        cairo_surface_destroy(impl_->surface);
        throw Error("cairo cannot make a " + std::to_string(width) + " x " + std::to_string(height) +
                    " mask: " + why);
    }
    cairo_set_source_rgba(impl_->cr, 0, 0, 0, 1);
    cairo_set_antialias(impl_->cr, CAIRO_ANTIALIAS_GRAY);
}

Mask::~Mask() {
    std::lock_guard<std::mutex> g(pangoMutex());
    cairo_destroy(impl_->cr);
    cairo_surface_destroy(impl_->surface);
}

int Mask::width() const { return impl_->width; }
int Mask::height() const { return impl_->height; }

void Mask::text(double x, double y, const std::string& text, const Font& font, Align align, bool markup) {
    std::lock_guard<std::mutex> g(pangoMutex());
    Layout layout = makeLayout(impl_->cr, text, font, align, markup);
    cairo_move_to(impl_->cr, x, y);
    pango_cairo_show_layout(impl_->cr, layout.get());
    cairo_new_path(impl_->cr);
}

void Mask::line(double x0, double y0, double x1, double y1, double width) {
    std::lock_guard<std::mutex> g(pangoMutex());
    cairo_set_line_width(impl_->cr, width);
    cairo_set_line_cap(impl_->cr, CAIRO_LINE_CAP_BUTT);
    cairo_move_to(impl_->cr, x0, y0);
    cairo_line_to(impl_->cr, x1, y1);
    cairo_stroke(impl_->cr);
}

void Mask::rectangle(double x, double y, double w, double h, double radius) {
    std::lock_guard<std::mutex> g(pangoMutex());
    cairo_t* cr = impl_->cr;
    const double r = std::clamp(radius, 0.0, std::min(w, h) * 0.5);
    if (r <= 0) {
        cairo_rectangle(cr, x, y, w, h);
    } else {
        const double pi = std::numbers::pi;
        cairo_new_sub_path(cr);
        cairo_arc(cr, x + w - r, y + r, r, -pi / 2, 0);
        cairo_arc(cr, x + w - r, y + h - r, r, 0, pi / 2);
        cairo_arc(cr, x + r, y + h - r, r, pi / 2, pi);
        cairo_arc(cr, x + r, y + r, r, pi, 3 * pi / 2);
        cairo_close_path(cr);
    }
    cairo_fill(cr);
}

void Mask::frame(double x, double y, double w, double h, double lineWidth) {
    std::lock_guard<std::mutex> g(pangoMutex());
    cairo_set_line_width(impl_->cr, lineWidth);
    cairo_set_line_join(impl_->cr, CAIRO_LINE_JOIN_MITER);
    cairo_rectangle(impl_->cr, x, y, w, h);
    cairo_stroke(impl_->cr);
}

const unsigned char* Mask::pixels(int& stride) const {
    std::lock_guard<std::mutex> g(pangoMutex());
    cairo_surface_flush(impl_->surface);
    stride = cairo_image_surface_get_stride(impl_->surface);
    return cairo_image_surface_get_data(impl_->surface);
}

float Mask::coverage(int x, int y) const {
    int stride = 0;
    const unsigned char* data = pixels(stride);
    return float(data[std::size_t(y) * std::size_t(stride) + std::size_t(x)]) / 255.0f;
}

TextBox measure(const std::string& text, const Font& font, Align align, bool markup) {
    std::lock_guard<std::mutex> g(pangoMutex());
    cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
    cairo_t* cr = cairo_create(s);
    TextBox box;
    try {
        Layout layout = makeLayout(cr, text, font, align, markup);
        box = boxOf(layout.get());
    } catch (...) {
        cairo_destroy(cr);
        cairo_surface_destroy(s);
        throw;
    }
    cairo_destroy(cr);
    cairo_surface_destroy(s);
    return box;
}

std::string resolvedFamily(const std::string& family) {
    std::lock_guard<std::mutex> g(pangoMutex());
    PangoFontMap* map = pango_cairo_font_map_get_default();
    PangoContext* context = pango_font_map_create_context(map);
    PangoFontDescription* desc = pango_font_description_from_string(family.c_str());
    pango_font_description_set_absolute_size(desc, 12 * PANGO_SCALE);
    std::string out;
    if (PangoFont* font = pango_font_map_load_font(map, context, desc)) {
        PangoFontDescription* used = pango_font_describe(font);
        if (const char* f = pango_font_description_get_family(used)) out = f;
        pango_font_description_free(used);
        g_object_unref(font);
    }
    pango_font_description_free(desc);
    g_object_unref(context);
    return out;
}

Overlay beginOverlay(Context& ctx, const BufferPtr& in) {
    std::vector<ChannelDesc> fresh{"R", "G", "B"};
    if (in->hasChannel("A")) fresh.push_back("A");
    Overlay o;
    o.buffer = ctx.derive(in, fresh, Fill::None);
    o.planes.width = in->width();
    o.planes.height = in->height();
    float** dst[4] = {&o.planes.r, &o.planes.g, &o.planes.b, &o.planes.a};
    for (std::size_t c = 0; c < fresh.size(); ++c) {
        const float* src = in->requireFloat(fresh[c].name);
        *dst[c] = o.buffer->writeFloat(fresh[c].name);
        std::copy(src, src + in->pixelCount(), *dst[c]);
    }
    return o;
}

void paint(const Mask& mask, int ox, int oy, Color color, const RgbaPlanes& image) {
    const float enc[3] = {linearToSrgb(std::clamp(color.r, 0.0f, 1.0f)), linearToSrgb(std::clamp(color.g, 0.0f, 1.0f)),
                          linearToSrgb(std::clamp(color.b, 0.0f, 1.0f))};
    float* planes[3] = {image.r, image.g, image.b};
    const int x0 = std::max(0, ox), y0 = std::max(0, oy);
    const int x1 = std::min(image.width, ox + mask.width()), y1 = std::min(image.height, oy + mask.height());
    int stride = 0;
    const unsigned char* cover = mask.pixels(stride);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const float k = float(cover[std::size_t(y - oy) * std::size_t(stride) + std::size_t(x - ox)]) / 255.0f;
            const float ao = k * std::clamp(color.a, 0.0f, 1.0f);
            if (ao <= 0) continue;
            const std::size_t i = std::size_t(y) * std::size_t(image.width) + std::size_t(x);
            // NaN alpha or colour underneath counts as nothing there.
            float ab = image.a ? image.a[i] : 1.0f;
            if (!(ab >= 0)) ab = 0;
            ab = std::min(ab, 1.0f);
            const float a = ao + ab * (1.0f - ao);
            for (int c = 0; c < 3; ++c) {
                float below = planes[c][i];
                if (!std::isfinite(below)) below = 0;
                const float mixed = (enc[c] * ao + linearToSrgb(std::clamp(below, 0.0f, 1.0f)) * ab * (1.0f - ao)) / a;
                planes[c][i] = srgbToLinear(mixed);
            }
            if (image.a) image.a[i] = a;
        }
}

}  // namespace darkroom::text
