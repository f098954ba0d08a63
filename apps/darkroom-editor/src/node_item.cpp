#include "node_item.h"

#include "channel_port.h"
#include "param_widget.h"

#include <QBrush>
#include <QGraphicsProxyWidget>
#include <QPainter>
#include <QPen>

namespace editor {
namespace {

constexpr qreal kWidth = 270, kHeader = 34, kRow = 26, kPortR = 6, kBadge = 20;

QColor portColour(darkroom::PortType t) {
    using T = darkroom::PortType;
    switch (t) {
    case T::Image: return QColor(90, 170, 250);
    case T::Float:
    case T::Int: return QColor(120, 220, 120);
    case T::Bool: return QColor(230, 200, 80);
    case T::Color:
    case T::ColorMap: return QColor(240, 120, 200);
    default: return QColor(200, 200, 200);
    }
}

}  // namespace

// The time badge above a node's top-right corner.
class BadgeItem : public QGraphicsItem {
public:
    explicit BadgeItem(QGraphicsItem* parent) : QGraphicsItem(parent) {}
    QRectF boundingRect() const override { return rect_; }
    void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override {
        if (text_.isEmpty()) return;
        p->setRenderHint(QPainter::Antialiasing);
        p->setPen(Qt::NoPen);
        p->setBrush(ran_ ? QColor(40, 120, 60) : QColor(70, 72, 78));
        p->drawRoundedRect(rect_, 4, 4);
        p->setFont(font());
        p->setPen(ran_ ? QColor(235, 255, 235) : QColor(190, 190, 190));
        p->drawText(rect_, Qt::AlignCenter, text_);
    }
    void set(const QString& text, bool ran) {
        if (text == text_ && ran == ran_) return;
        prepareGeometryChange();
        text_ = text;
        ran_ = ran;
        const qreal w = text_.isEmpty() ? 0 : QFontMetricsF(font()).horizontalAdvance(text_) + 12;
        rect_ = QRectF(-w, -kBadge - 1, w, kBadge - 2);  // right-aligned at the item's position
        update();
    }
    const QString& text() const { return text_; }
    bool ran() const { return ran_; }

private:
    static QFont font() {
        QFont f;
        f.setPointSizeF(f.pointSizeF() * 0.9);
        return f;
    }
    QString text_;
    bool ran_ = false;
    QRectF rect_;
};

PortItem::PortItem(const darkroom::PortSpec& spec, bool output, QGraphicsItem* parent)
    : QGraphicsEllipseItem(-kPortR, -kPortR, 2 * kPortR, 2 * kPortR, parent), spec_(spec), output_(output) {
    setBrush(portColour(spec.type));
    setPen(QPen(Qt::black, 1));
    setToolTip(QStringLiteral("%1 (%2%3)\n%4")
                   .arg(QString::fromStdString(spec.name), QString::fromUtf8(darkroom::toString(spec.type)),
                        spec.multiple ? QStringLiteral(", multiple") : QString(),
                        QString::fromStdString(spec.doc)));
}

QString PortItem::nodeName() const { return static_cast<NodeItem*>(parentItem())->name(); }

NodeItem::NodeItem(const darkroom::Node& node, const darkroom::PortList& ports, const QString& baseFolder)
    : name_(QString::fromStdString(node.name)), type_(node.type), badge_(new BadgeItem(this)) {
    setFlags(ItemIsMovable | ItemIsSelectable | ItemSendsGeometryChanges);
    badge_->setPos(kWidth, 0);
    qreal y = kHeader + kRow / 2;
    for (const auto& out : ports.outputs) {
        auto* p = new PortItem(out, true, this);
        p->setPos(kWidth, y);
        outputs_[QString::fromStdString(out.name)] = p;
        y += kRow;
    }
    for (const auto& in : ports.inputs) {
        const QString n = QString::fromStdString(in.name);
        auto* p = new PortItem(in, false, this);
        p->setPos(0, y);
        inputs_[n] = p;
        if (!in.isImage()) {
            auto* w = new ParamWidget(in, baseFolder);
            w->setFixedWidth(int(kWidth - 110));
            auto* proxy = new QGraphicsProxyWidget(this);
            proxy->setWidget(w);
            proxy->setPos(100, y - kRow / 2 + 2);
            proxy->resize(kWidth - 110, kRow - 4);
            proxies_[n] = proxy;
            widgets_[n] = w;
            connect(w, &ParamWidget::edited, this,
                    [this, n](const darkroom::Value& v) { emit parameterEdited(name_, n, v); });
            connect(w, &ParamWidget::interaction, this, &NodeItem::interaction);
        }
        y += kRow;
    }
    height_ = y - kRow / 2 + 8;
    if (node.placeholder) setError(QStringLiteral("Unknown type %1: kept as written").arg(QString::fromStdString(type_)));
}

QRectF NodeItem::boundingRect() const { return QRectF(-kPortR, 0, kWidth + 2 * kPortR, height_); }

qreal NodeItem::width() { return kWidth; }

const QString& NodeItem::badgeText() const { return badge_->text(); }

bool NodeItem::badgeRan() const { return badge_->ran(); }

void NodeItem::setTiming(double seconds, bool ran, bool preview) {
    if (waiting()) {
        badge_->set(QStringLiteral("waiting for input"), false);
        return;
    }
    QString text;
    if (seconds >= 0)
        text = (seconds < 0.9995 ? QStringLiteral("%1 ms").arg(seconds * 1000, 0, 'f', seconds < 0.01 ? 1 : 0)
                                 : QStringLiteral("%1 s").arg(seconds, 0, 'f', 2)) +
               (preview && ran ? QStringLiteral(" (preview)") : ran ? QString() : QStringLiteral(" cached"));
    badge_->set(text, ran);
}

void NodeItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
    const QRectF r(0, 0, kWidth, height_);
    p->setRenderHint(QPainter::Antialiasing);
    QPen pen(error_.isEmpty() ? (isSelected() ? QColor(255, 200, 60) : QColor(20, 20, 20)) : QColor(230, 40, 40),
             error_.isEmpty() && !isSelected() ? 1.0 : 3.0);
    if (error_.isEmpty() && waiting()) {
        pen = QPen(isSelected() ? QColor(255, 200, 60) : QColor(170, 175, 185), 2.0, Qt::DashLine);
    }
    p->setPen(pen);
    p->setBrush(QColor(58, 60, 66));
    p->drawRoundedRect(r, 6, 6);
    p->setBrush(QColor(40, 90, 140));
    p->drawRoundedRect(QRectF(0, 0, kWidth, kHeader - 4), 6, 6);
    p->setPen(Qt::white);
    QFont f = p->font();
    f.setBold(true);
    p->setFont(f);
    p->drawText(QRectF(8, 0, kWidth - 16, kHeader - 4), Qt::AlignVCenter | Qt::AlignLeft, name_);
    f.setBold(false);
    p->setFont(f);
    p->setPen(QColor(200, 210, 220));
    p->drawText(QRectF(8, 0, kWidth - 16, kHeader - 4), Qt::AlignVCenter | Qt::AlignRight,
                QString::fromStdString(type_));
    p->setPen(QColor(225, 225, 225));
    for (const auto& [n, port] : outputs_)
        p->drawText(QRectF(100, port->y() - kRow / 2, kWidth - 112, kRow), Qt::AlignVCenter | Qt::AlignRight, n);
    for (const auto& [n, port] : inputs_)
        p->drawText(QRectF(10, port->y() - kRow / 2, 88, kRow), Qt::AlignVCenter | Qt::AlignLeft, n);
}

PortItem* NodeItem::port(const QString& name, bool output) const {
    const auto& m = output ? outputs_ : inputs_;
    const auto it = m.find(name);
    return it == m.end() ? nullptr : it->second;
}

ParamWidget* NodeItem::paramWidget(const QString& port) const {
    const auto it = widgets_.find(port);
    return it == widgets_.end() ? nullptr : it->second;
}

void NodeItem::refresh(const darkroom::Graph& g) {
    const darkroom::Node* node = g.node(name_.toStdString());
    if (!node) return;
    for (auto& [n, w] : widgets_) {
        const std::string port = n.toStdString();
        const bool connected = !g.edgesInto(node->name, port).empty();
        proxies_[n]->setVisible(!connected);
        const darkroom::Value* v = node->parameter(port);
        w->setValue(v ? *v : w->port().defaultValue);
    }
}

void NodeItem::setChannelChoices(const QStringList& channels) {
    for (auto& [n, w] : widgets_)
        if (isChannelPort(w->port())) w->setChoices(channels);
}

void NodeItem::setError(const QString& message) {
    if (message == error_) return;
    error_ = message;
    setToolTip(error_.isEmpty() ? waiting_ : error_);
    QGraphicsObject::update();
}

void NodeItem::setWaiting(const QString& why) {
    if (why == waiting_) return;
    waiting_ = why;
    badge_->set(waiting() ? QStringLiteral("waiting for input") : QString(), false);
    setToolTip(error_.isEmpty() ? waiting_ : error_);
    QGraphicsObject::update();
}

}  // namespace editor
