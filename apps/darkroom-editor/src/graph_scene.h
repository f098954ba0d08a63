#pragma once
// The node graph as a QGraphicsScene kept in step with the Document: node
// items, edges, connecting by dragging between ports, moving, deleting.
#include <QGraphicsScene>

#include <map>

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
    void deleteSelection();
    void sync();  // rebuilds what changed in the document

signals:
    void message(const QString& text);  // for the status bar (refused connections, errors)

protected:
    void mousePressEvent(QGraphicsSceneMouseEvent* e) override;
    void mouseMoveEvent(QGraphicsSceneMouseEvent* e) override;
    void mouseReleaseEvent(QGraphicsSceneMouseEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;

private:
    PortItem* portAt(QPointF scenePos) const;
    void finishConnect(PortItem* target);
    void commitMoves();
    void onParameterEdited(const QString& node, const QString& port, const darkroom::Value& v);

    Document* doc_;
    std::map<QString, NodeItem*> nodes_;
    std::vector<QGraphicsPathItem*> edges_;
    PortItem* dragFrom_ = nullptr;
    QGraphicsPathItem* dragLine_ = nullptr;
    bool syncing_ = false;
};

}  // namespace editor
