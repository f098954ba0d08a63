#include "param_widget.h"

#include "channel_port.h"

#include <darkroom/colormap.h>
#include <darkroom/srgb.h>

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QMouseEvent>
#include <QPainter>
#include <QPixmap>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>

#include <cmath>

namespace editor {
namespace {

constexpr int kSliderSteps = 1000;

bool sliderRange(const darkroom::PortSpec& p) {
    return p.minimum && p.maximum && *p.maximum > *p.minimum && *p.maximum - *p.minimum <= 1e6;
}

int toByte(float linear) {
    return std::clamp(int(std::lround(darkroom::linearToSrgb(linear) * 255.0f)), 0, 255);
}

}  // namespace

QPixmap colorMapStrip(const std::string& spec, int w, int h) {
    QPixmap pm(w, h);
    pm.fill(Qt::gray);
    try {
        const auto map = darkroom::loadColorMap(spec);
        QPainter p(&pm);
        for (int x = 0; x < w; ++x) {
            const auto c = map.sample(double(x) / std::max(1, w - 1));
            p.setPen(QColor(toByte(c.r), toByte(c.g), toByte(c.b)));
            p.drawLine(x, 0, x, h - 1);
        }
    } catch (const std::exception&) {
        // A path that does not load shows grey; the node reports the error.
    }
    return pm;
}

ParamWidget::ParamWidget(const darkroom::PortSpec& port, const QString& baseFolder, QWidget* parent)
    : QWidget(parent), port_(port), baseFolder_(baseFolder) {
    auto* lay = new QHBoxLayout(this);
    lay->setContentsMargins(0, 0, 0, 0);
    lay->setSpacing(2);
    using T = darkroom::PortType;
    switch (port.type) {
    case T::Float:
    case T::Int:
        buildNumberBox(lay);
        break;
    case T::Bool:
        check_ = new QCheckBox;
        lay->addWidget(check_);
        connect(check_, &QCheckBox::toggled, this, [this](bool b) {
            if (!updating_) emit edited(darkroom::Value(b));
        });
        break;
    case T::Enum:
    case T::ColorMap:
        combo_ = new QComboBox;
        for (const auto& c : port.choices) {
            if (port.type == T::ColorMap)
                combo_->addItem(QIcon(colorMapStrip(c, 64, 12)), QString::fromStdString(c));
            else
                combo_->addItem(QString::fromStdString(c));
        }
        if (port.type == T::ColorMap) {
            combo_->setIconSize(QSize(64, 12));
            combo_->setEditable(true);  // a ParaView JSON path is allowed too
            // Empty: the node picks (ColorMapping: the database's stored map, else viridis).
            combo_->lineEdit()->setPlaceholderText(tr("automatic"));
        }
        lay->addWidget(combo_, 1);
        connect(combo_, &QComboBox::textActivated, this, [this](const QString& t) { emitText(t); });
        break;
    case T::Color:  // linear in the graph, sRGB on screen and in the dialog
        colour_ = new QPushButton;
        lay->addWidget(colour_, 1);
        connect(colour_, &QPushButton::clicked, this, [this] {
            const QColor c = QColorDialog::getColor(
                QColor::fromRgbF(darkroom::linearToSrgb(colourValue_.r), darkroom::linearToSrgb(colourValue_.g),
                                 darkroom::linearToSrgb(colourValue_.b), colourValue_.a), this,
                QString::fromStdString(port_.name), QColorDialog::ShowAlphaChannel);
            if (c.isValid())
                emit edited(darkroom::Value(darkroom::Color{darkroom::srgbToLinear(float(c.redF())), darkroom::srgbToLinear(float(c.greenF())),
                                                            darkroom::srgbToLinear(float(c.blueF())), float(c.alphaF())}));
        });
        break;
    default: {
        if (isChannelPort(port)) {
            buildChannelBox(lay);
            break;
        }
        line_ = new QLineEdit;
        lay->addWidget(line_, 1);
        connect(line_, &QLineEdit::editingFinished, this, [this] {
            if (line_->isModified()) emitText(line_->text());
            line_->setModified(false);
        });
        if (port.type == T::Path || port.type == T::OutputPath) {
            auto* b = new QPushButton(QStringLiteral("…"));
            b->setFixedWidth(24);
            lay->addWidget(b);
            // What a node reads is opened; what it writes is saved (the
            // dialog asks before naming an existing file).
            connect(b, &QPushButton::clicked, this, [this] {
                const QString title = QString::fromStdString(port_.name);
                const QString f = port_.type == T::Path ? QFileDialog::getOpenFileName(this, title, baseFolder_)
                                                        : QFileDialog::getSaveFileName(this, title, baseFolder_);
                if (!f.isEmpty()) emitText(f);
            });
        }
    }
    }
    setToolTip(QString::fromStdString(port.name + ": " + port.doc));
    setValue(port.defaultValue);
}

double ParamWidget::scrubStep(double start) const {
    // One pixel changes the value by 0.5 % of its size (at least 0.001), so
    // a 200-pixel drag doubles it whatever its scale; integers by >= 1/10.
    const double step = std::max(std::abs(start) * 0.005, 0.001);
    return port_.type == darkroom::PortType::Int ? std::max(step, 0.1) : step;
}

bool ParamWidget::eventFilter(QObject* watched, QEvent* e) {
    auto* edit = qobject_cast<QLineEdit*>(watched);
    if (!edit || !spin_ || edit->hasFocus()) return QWidget::eventFilter(watched, e);  // typing: normal editing
    switch (e->type()) {
    case QEvent::MouseButtonPress: {
        auto* m = static_cast<QMouseEvent*>(e);
        if (m->button() != Qt::LeftButton) break;
        pressed_ = true;
        scrubbing_ = false;
        pressAt_ = m->globalPosition();
        pressValue_ = spin_->value();
        return true;
    }
    case QEvent::MouseMove: {
        auto* m = static_cast<QMouseEvent*>(e);
        if (!pressed_) break;
        const double dx = m->globalPosition().x() - pressAt_.x();
        if (!scrubbing_ && std::abs(dx) < 3) return true;
        if (!scrubbing_) {
            scrubbing_ = true;
            emit interaction(true);
        }
        const double fine = (m->modifiers() & Qt::ControlModifier) ? 0.1 : 1.0;
        spin_->setValue(pressValue_ + dx * scrubStep(pressValue_) * fine);  // emits through the spin box
        return true;
    }
    case QEvent::MouseButtonRelease: {
        if (!pressed_) break;
        pressed_ = false;
        if (scrubbing_) {
            scrubbing_ = false;
            emit interaction(false);
        } else {  // a click: edit the number as text
            spin_->setFocus(Qt::MouseFocusReason);
            edit->selectAll();
        }
        return true;
    }
    default:
        break;
    }
    return QWidget::eventFilter(watched, e);
}

void ParamWidget::buildNumberBox(QHBoxLayout* lay) {
    spin_ = new QDoubleSpinBox;
    const bool isInt = port_.type == darkroom::PortType::Int;
    spin_->setDecimals(isInt ? 0 : 3);
    spin_->setRange(port_.minimum.value_or(-1e12), port_.maximum.value_or(1e12));
    spin_->setSingleStep(isInt ? 1 : 0.01);
    spin_->setKeyboardTracking(false);
    lay->addWidget(spin_, 1);
    if (sliderRange(port_)) {
        slider_ = new QSlider(Qt::Horizontal);
        slider_->setRange(0, isInt ? int(*port_.maximum - *port_.minimum) : kSliderSteps);
        lay->addWidget(slider_, 2);
        connect(slider_, &QSlider::sliderPressed, this, [this] { emit interaction(true); });
        connect(slider_, &QSlider::sliderReleased, this, [this] { emit interaction(false); });
        connect(slider_, &QSlider::valueChanged, this, [this, isInt](int s) {
            if (updating_) return;
            const double v = isInt ? *port_.minimum + s
                                   : *port_.minimum + (*port_.maximum - *port_.minimum) * s / kSliderSteps;
            spin_->setValue(v);  // emits through the spin box
        });
    }
    if (!slider_)
        if (auto* edit = spin_->findChild<QLineEdit*>()) {
            edit->installEventFilter(this);
            edit->setCursor(Qt::SizeHorCursor);
        }
    connect(spin_, &QDoubleSpinBox::valueChanged, this, [this, isInt](double v) {
        if (slider_) {
            QSignalBlocker b(slider_);
            slider_->setValue(isInt ? int(v - *port_.minimum)
                                    : int(std::lround((v - *port_.minimum) / (*port_.maximum - *port_.minimum) * kSliderSteps)));
        }
        if (updating_) return;
        emit edited(isInt ? darkroom::Value(std::int64_t(std::llround(v))) : darkroom::Value(v));
    });
}

void ParamWidget::buildChannelBox(QHBoxLayout* lay) {
    // A channel of the input: its channels once an evaluation saw them,
    // or any text (a channel an upstream edit is about to add).
    combo_ = new QComboBox;
    combo_->setEditable(true);
    combo_->setInsertPolicy(QComboBox::NoInsert);
    combo_->setMinimumContentsLength(6);
    combo_->lineEdit()->setPlaceholderText(tr("automatic"));
    lay->addWidget(combo_, 1);
    connect(combo_, &QComboBox::textActivated, this, [this](const QString& t) { emitText(t); });
    connect(combo_->lineEdit(), &QLineEdit::editingFinished, this, [this] { emitText(combo_->currentText()); });
}

void ParamWidget::setChoices(const QStringList& items) {
    if (!combo_ || !combo_->isEditable()) return;
    QStringList now;
    for (int i = 0; i < combo_->count(); ++i) now << combo_->itemText(i);
    if (now == items) return;
    QSignalBlocker b(combo_);
    const QString text = combo_->currentText();
    combo_->clear();
    combo_->addItems(items);
    combo_->setCurrentIndex(int(items.indexOf(text)));
    combo_->setEditText(text);
}

void ParamWidget::emitText(const QString& text) {
    // An editable box reports a choice and then the end of editing: the
    // same value is one edit, not two.
    if (port_.type == darkroom::PortType::String && text == text_) return;
    text_ = text;
    try {
        emit edited(darkroom::parseValue(port_.type, text.toStdString()));
    } catch (const std::exception& e) {
        setToolTip(QString::fromStdString(e.what()));
    }
}

void ParamWidget::setValue(const darkroom::Value& v) {
    if (v.empty()) return;
    updating_ = true;
    try {
        if (spin_) spin_->setValue(v.asFloat());
        if (check_) check_->setChecked(v.asBool());
        if (combo_) combo_->setCurrentText(QString::fromStdString(v.asString()));
        if (port_.type == darkroom::PortType::String) text_ = QString::fromStdString(v.asString());
        if (line_ && !line_->hasFocus()) line_->setText(QString::fromStdString(darkroom::formatValue(port_.type, v)));
        if (colour_) {
            colourValue_ = v.asColor();
            colour_->setStyleSheet(QStringLiteral("background: rgb(%1,%2,%3)")
                                       .arg(toByte(colourValue_.r)).arg(toByte(colourValue_.g)).arg(toByte(colourValue_.b)));
        }
    } catch (const std::exception&) {
        // A value of the wrong type leaves the widget as it was.
    }
    updating_ = false;
}

}  // namespace editor
