#pragma once
// The value widget shown beside an unconnected value input: spin box and
// slider for ranged numbers, check box, enum combo, colour button, colour-map
// combo with preview strips, file chooser, line edit. Numbers without a
// finite range are dragged on their field (left-drag sideways, Ctrl for
// fine steps; a click without dragging edits the text), as in Blender.
#include <darkroom/port.h>

#include <QWidget>

#include <functional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QHBoxLayout;
class QLineEdit;
class QPixmap;
class QPushButton;
class QSlider;

namespace editor {

class ParamWidget : public QWidget {
    Q_OBJECT
public:
    // `baseFolder` is where the file chooser starts (the pipeline's folder).
    ParamWidget(const darkroom::PortSpec& port, const QString& baseFolder, QWidget* parent = nullptr);
    void setValue(const darkroom::Value& v);  // no edited() signal
    // A channel port's drop-down: the input's channels (the text typed or
    // set stays).
    void setChoices(const QStringList& items);
    const darkroom::PortSpec& port() const { return port_; }
    // For tests: the slider of a ranged number, else null; the number field.
    QSlider* slider() const { return slider_; }
    QDoubleSpinBox* spinBox() const { return spin_; }

signals:
    void edited(const darkroom::Value& v);
    // A drag of the slider or of the number field starts or ends.
    void interaction(bool dragging);

protected:
    bool eventFilter(QObject* watched, QEvent* e) override;

private:
    void emitText(const QString& text);
    void buildNumberBox(QHBoxLayout* lay);  // spin box, and a slider for a finite range
    void buildChannelBox(QHBoxLayout* lay);
    double scrubStep(double start) const;
    bool pressed_ = false, scrubbing_ = false;
    QPointF pressAt_;
    double pressValue_ = 0;
    darkroom::PortSpec port_;
    QString baseFolder_;
    QSlider* slider_ = nullptr;
    QDoubleSpinBox* spin_ = nullptr;
    QCheckBox* check_ = nullptr;
    QComboBox* combo_ = nullptr;
    QLineEdit* line_ = nullptr;
    QPushButton* colour_ = nullptr;
    QString text_;  // a string port's value as last set or emitted
    darkroom::Color colourValue_;
    bool updating_ = false;
};

// A horizontal strip of a colour map (sRGB-encoded for display).
QPixmap colorMapStrip(const std::string& spec, int w, int h);

}  // namespace editor
