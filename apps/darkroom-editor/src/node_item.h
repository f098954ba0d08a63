#pragma once
// One node in the graph view: a titled box with input ports on the left,
// outputs on the right, the value widget of each unconnected value input,
// and above it a badge with the time of its last run (green: it ran for the
// frame on screen; grey: its result came from the cache).
#include <darkroom/core/graph.h>

#include <QGraphicsEllipseItem>
#include <QGraphicsObject>

#include <map>

class QGraphicsProxyWidget;

namespace editor {

class ParamWidget;
class BadgeItem;

class PortItem : public QGraphicsEllipseItem {
public:
    enum { Type = UserType + 1 };
    PortItem(const darkroom::PortSpec& spec, bool output, QGraphicsItem* parent);
    int type() const override { return Type; }
    const darkroom::PortSpec& spec() const { return spec_; }
    bool isOutput() const { return output_; }
    QString nodeName() const;

private:
    darkroom::PortSpec spec_;
    bool output_;
};

class NodeItem : public QGraphicsObject {
    Q_OBJECT
public:
    enum { Type = UserType + 2 };
    NodeItem(const darkroom::Node& node, const darkroom::PortList& ports, const QString& baseFolder);
    int type() const override { return Type; }
    QRectF boundingRect() const override;
    void paint(QPainter* p, const QStyleOptionGraphicsItem* o, QWidget* w) override;

    const QString& name() const { return name_; }
    const std::string& typeName() const { return type_; }
    PortItem* port(const QString& name, bool output) const;
    ParamWidget* paramWidget(const QString& port) const;
    // Shows the node's current values; hides widgets of connected inputs.
    void refresh(const darkroom::Graph& g);
    void setError(const QString& message);  // empty clears
    // The channels of the image input, offered by its channel ports.
    void setChannelChoices(const QStringList& channels);
    // The badge: seconds < 0 hides it.
    void setTiming(double seconds, bool ran, bool preview);
    const QString& badgeText() const;
    bool badgeRan() const;
    bool failed() const { return !error_.isEmpty(); }
    // Waiting for input: a required image input is not connected yet. Not
    // a failure: drawn with a dashed border, the badge says so.
    void setWaiting(const QString& why);  // empty clears
    bool waiting() const { return !waiting_.isEmpty(); }
    static qreal width();

signals:
    void parameterEdited(const QString& node, const QString& port, const darkroom::Value& v);
    void interaction(bool dragging);  // a value widget's drag starts or ends

private:
    QString name_;
    std::string type_;
    QString error_;
    QString waiting_;
    // Its own item, so a new time repaints the badge, not the node's widgets.
    BadgeItem* badge_;
    qreal height_ = 0;
    std::map<QString, PortItem*> inputs_, outputs_;
    std::map<QString, QGraphicsProxyWidget*> proxies_;
    std::map<QString, ParamWidget*> widgets_;
};

}  // namespace editor
