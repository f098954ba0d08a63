#pragma once
// The node graph as a QGraphicsScene kept in step with the Document: node
// items, edges, connecting by dragging between ports, moving, deleting.
// Pressing on a connected input picks its connection up (as in Blender's
// compositor): dropped on another input it moves there, dropped anywhere
// else it is removed. A connection dropped on a taken single input
// replaces the one there.
#include <QGraphicsScene>
#include <QStringList>

#include <darkroom/core/graph.h>

#include <map>
#include <optional>

class QGraphicsPathItem;

namespace darkroom { class Value; }

namespace editor {

class Document;
class NodeItem;
class PortItem;

class GraphScene : public QGraphicsScene {
    Q_OBJECT
public:
    explicit GraphScene(Document* doc, QObject* parent = nullptr);

    NodeItem* nodeItem(const QString& name) const;
    // Scene position of a port (for tests and the edge drawing).
    QPointF portPos(const QString& node, const QString& port, bool output) const;
    QString selectedNode() const;  // the first selected node, or empty
    void setErrors(const std::map<QString, QString>& errors);  // node -> message
    // Nodes waiting for input (node -> which input); the others are not.
    void setWaiting(const std::map<QString, QString>& waiting);
    // The channels of the image flowing into each node, for its channel
    // ports' drop-downs (nodes left out keep what they had).
    void setInputChannels(const std::map<QString, QStringList>& channels);
    struct Timing {
        double seconds = -1;  // < 0: no badge
        bool ran = false;
    };
    // Badges; nodes left out lose theirs. `preview`: the times are of a
    // reduced-resolution frame.
    void setTimings(const std::map<QString, Timing>& timings, bool preview);
    void deleteSelection();
    void sync();  // rebuilds what changed in the document

signals:
    void message(const QString& text);  // for the status bar (refused connections, errors)
    void interaction(bool dragging);    // a value widget's drag starts or ends

protected:
    void mousePressEvent(QGraphicsSceneMouseEvent* e) override;
    void mouseMoveEvent(QGraphicsSceneMouseEvent* e) override;
    void mouseReleaseEvent(QGraphicsSceneMouseEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;

private:
    PortItem* portAt(QPointF scenePos) const;
    void finishConnect(PortItem* target);
    void finishDetached(PortItem* target);
    QGraphicsPathItem* edgeItem(const darkroom::Edge& e) const;
    void commitMoves();
    void onParameterEdited(const QString& node, const QString& port, const darkroom::Value& v);

    Document* doc_;
    std::map<QString, NodeItem*> nodes_;
    std::vector<QGraphicsPathItem*> edges_;
    PortItem* dragFrom_ = nullptr;
    QGraphicsPathItem* dragLine_ = nullptr;
    std::optional<darkroom::Edge> detached_;  // the connection picked up from an input
    bool syncing_ = false;
};

}  // namespace editor
