#pragma once
// The value widget shown beside an unconnected value input: spin box and
// slider for ranged numbers, check box, enum combo, colour button, colour-map
// combo with preview strips, file chooser, line edit.
#include <darkroom/port.h>

#include <QWidget>

#include <functional>

namespace editor {

class ParamWidget : public QWidget {
    Q_OBJECT
public:
    // `baseFolder` is where the file chooser starts (the pipeline's folder).
    ParamWidget(const darkroom::PortSpec& port, const QString& baseFolder, QWidget* parent = nullptr);
    void setValue(const darkroom::Value& v);  // no edited() signal
    const darkroom::PortSpec& port() const { return port_; }
    // For tests: the slider of a ranged number, else null.
    class QSlider* slider() const { return slider_; }

signals:
    void edited(const darkroom::Value& v);

private:
    void emitText(const QString& text);
    darkroom::PortSpec port_;
    QString baseFolder_;
    class QSlider* slider_ = nullptr;
    class QDoubleSpinBox* spin_ = nullptr;
    class QCheckBox* check_ = nullptr;
    class QComboBox* combo_ = nullptr;
    class QLineEdit* line_ = nullptr;
    class QPushButton* colour_ = nullptr;
    darkroom::Color colourValue_;
    bool updating_ = false;
};

// A horizontal strip of a colour map (sRGB-encoded for display).
class QPixmap colorMapStrip(const std::string& spec, int w, int h);

}  // namespace editor
