#include "graph_scene.h"

#include "document.h"
#include "layout.h"
#include "node_item.h"

#include <QGraphicsPathItem>
#include <QGraphicsSceneMouseEvent>
#include <QKeyEvent>
#include <QPainterPath>
#include <QPen>
#include <QSet>
#include <QToolTip>

namespace editor {
namespace {

QPainterPath edgePath(QPointF a, QPointF b) {
    QPainterPath p(a);
    const qreal dx = std::max<qreal>(40, std::abs(b.x() - a.x()) / 2);
    p.cubicTo(a + QPointF(dx, 0), b - QPointF(dx, 0), b);
    return p;
}

darkroom::Endpoint endpoint(const PortItem* p) {
    return {p->nodeName().toStdString(), p->spec().name};
}

}  // namespace

GraphScene::GraphScene(Document* doc, QObject* parent) : QGraphicsScene(parent), doc_(doc) {
    setBackgroundBrush(QColor(38, 40, 44));
    setSceneRect(-4000, -4000, 10000, 10000);  // room to pan around any graph
    connect(doc_, &Document::changed, this, &GraphScene::sync);
    sync();
}

NodeItem* GraphScene::nodeItem(const QString& name) const {
    const auto it = nodes_.find(name);
    return it == nodes_.end() ? nullptr : it->second;
}

QPointF GraphScene::portPos(const QString& node, const QString& port, bool output) const {
    const NodeItem* n = nodeItem(node);
    const PortItem* p = n ? n->port(port, output) : nullptr;
    return p ? p->scenePos() : QPointF();
}

QString GraphScene::selectedNode() const {
    for (QGraphicsItem* i : selectedItems())
        if (i->type() == NodeItem::Type) return static_cast<NodeItem*>(i)->name();
    return {};
}

void GraphScene::setErrors(const std::map<QString, QString>& errors) {
    for (auto& [name, item] : nodes_) {
        const auto it = errors.find(name);
        item->setError(it == errors.end() ? QString() : it->second);
    }
}

void GraphScene::setWaiting(const std::map<QString, QString>& waiting) {
    for (auto& [name, item] : nodes_) {
        const auto it = waiting.find(name);
        item->setWaiting(it == waiting.end() ? QString() : it->second);
    }
}

void GraphScene::setInputChannels(const std::map<QString, QStringList>& channels) {
    for (const auto& [name, list] : channels)
        if (NodeItem* item = nodeItem(name)) item->setChannelChoices(list);
}

void GraphScene::setTimings(const std::map<QString, Timing>& timings, bool preview) {
    for (auto& [name, item] : nodes_) {
        const auto it = timings.find(name);
        if (it == timings.end()) item->setTiming(-1, false, preview);
        else item->setTiming(it->second.seconds, it->second.ran, preview);
    }
}

QGraphicsPathItem* GraphScene::edgeItem(const darkroom::Edge& e) const {
    for (auto* item : edges_)
        if (item->data(0).toString().toStdString() == e.from.node && item->data(1).toString().toStdString() == e.from.port &&
            item->data(2).toString().toStdString() == e.to.node && item->data(3).toString().toStdString() == e.to.port)
            return item;
    return nullptr;
}

void GraphScene::sync() {
    syncing_ = true;
    const darkroom::Graph& g = doc_->graph();
    QSet<QString> alive;
    for (const auto& n : g.nodes()) {
        const QString name = QString::fromStdString(n.name);
        alive.insert(name);
        NodeItem* item = nodeItem(name);
        if (item && item->typeName() != n.type) {
            // Out of the map first: deleting it deselects it, and the
            // selection's listeners walk the map.
            nodes_.erase(name);
            delete item;
            item = nullptr;
        }
        if (!item) {
            item = new NodeItem(n, g.ports(n), doc_->folder());
            addItem(item);
            nodes_[name] = item;
            connect(item, &NodeItem::parameterEdited, this, &GraphScene::onParameterEdited);
            connect(item, &NodeItem::interaction, this, &GraphScene::interaction);
        }
        if (const auto pos = nodePosition(n)) item->setPos(*pos);
        item->refresh(g);
    }
    for (auto it = nodes_.begin(); it != nodes_.end();) {
        if (alive.contains(it->first)) {
            ++it;
        } else {
            NodeItem* dead = it->second;
            it = nodes_.erase(it);  // before the delete, as above
            delete dead;
        }
    }
    // Edges are rebuilt only when they changed: a value edit (every step of
    // a drag) then repaints just the widget that changed.
    bool same = edges_.size() == g.edges().size();
    for (std::size_t i = 0; same && i < edges_.size(); ++i) same = edgeItem(g.edges()[i]) == edges_[i];
    if (!same) {
        for (auto* e : edges_) delete e;
        edges_.clear();
    }
    for (const auto& e : same ? std::vector<darkroom::Edge>{} : g.edges()) {
        const QString key = QString::fromStdString(e.from.str() + " -> " + e.to.str());
        auto* item = new QGraphicsPathItem;
        item->setPen(QPen(QColor(180, 190, 200), 2.5));
        item->setFlag(QGraphicsItem::ItemIsSelectable);
        item->setZValue(-1);
        item->setToolTip(key);
        item->setData(0, QString::fromStdString(e.from.node));
        item->setData(1, QString::fromStdString(e.from.port));
        item->setData(2, QString::fromStdString(e.to.node));
        item->setData(3, QString::fromStdString(e.to.port));
        addItem(item);
        edges_.push_back(item);
    }
    syncing_ = false;
    // Edge geometry follows the items, also while they are dragged.
    for (auto* e : edges_)
        e->setPath(edgePath(portPos(e->data(0).toString(), e->data(1).toString(), true),
                            portPos(e->data(2).toString(), e->data(3).toString(), false)));
}

PortItem* GraphScene::portAt(QPointF scenePos) const {
    // A little slack around the small port circles makes them easy to hit.
    for (QGraphicsItem* i : items(QRectF(scenePos - QPointF(5, 5), QSizeF(10, 10))))
        if (i->type() == PortItem::Type) return static_cast<PortItem*>(i);
    return nullptr;
}

void GraphScene::mousePressEvent(QGraphicsSceneMouseEvent* e) {
    if (e->button() == Qt::LeftButton) {
        if (PortItem* p = portAt(e->scenePos())) {
            dragFrom_ = p;
            detached_.reset();
            if (!p->isOutput()) {
                // A connected input: pick up its (last) connection from the output end.
                const auto into = doc_->graph().edgesInto(p->nodeName().toStdString(), p->spec().name);
                NodeItem* up = into.empty() ? nullptr : nodeItem(QString::fromStdString(into.back().from.node));
                PortItem* out = up ? up->port(QString::fromStdString(into.back().from.port), true) : nullptr;
                if (out) {
                    detached_ = into.back();
                    dragFrom_ = out;
                    if (auto* item = edgeItem(*detached_)) item->setVisible(false);
                }
            }
            dragLine_ = new QGraphicsPathItem;
            dragLine_->setPen(QPen(QColor(255, 220, 120), 2, Qt::DashLine));
            addItem(dragLine_);
            e->accept();
            return;
        }
    }
    QGraphicsScene::mousePressEvent(e);
}

void GraphScene::mouseMoveEvent(QGraphicsSceneMouseEvent* e) {
    if (dragFrom_) {
        const QPointF a = dragFrom_->scenePos();
        dragLine_->setPath(dragFrom_->isOutput() ? edgePath(a, e->scenePos()) : edgePath(e->scenePos(), a));
        e->accept();
        return;
    }
    QGraphicsScene::mouseMoveEvent(e);
    if (e->buttons() & Qt::LeftButton)
        for (auto* item : edges_)
            item->setPath(edgePath(portPos(item->data(0).toString(), item->data(1).toString(), true),
                                   portPos(item->data(2).toString(), item->data(3).toString(), false)));
}

void GraphScene::mouseReleaseEvent(QGraphicsSceneMouseEvent* e) {
    if (dragFrom_) {
        PortItem* target = portAt(e->scenePos());
        delete dragLine_;
        dragLine_ = nullptr;
        if (detached_) finishDetached(target);
        else if (target && target != dragFrom_) finishConnect(target);
        dragFrom_ = nullptr;
        detached_.reset();
        e->accept();
        return;
    }
    QGraphicsScene::mouseReleaseEvent(e);
    commitMoves();
}

namespace {

// Removes what occupies a single input `to`, so a new connection replaces it.
void freeInput(darkroom::Graph& g, const darkroom::Endpoint& to) {
    const darkroom::Node* n = g.node(to.node);
    const darkroom::PortSpec* in = n && !n->placeholder ? g.ports(*n).input(to.port) : nullptr;
    if (!in || in->multiple) return;
    for (const auto& e : g.edgesInto(to.node, to.port)) g.disconnect(e.from, e.to);
}

}  // namespace

void GraphScene::finishConnect(PortItem* target) {
    const PortItem* out = dragFrom_->isOutput() ? dragFrom_ : target;
    const PortItem* in = dragFrom_->isOutput() ? target : dragFrom_;
    if (out->isOutput() == in->isOutput()) {
        emit message(tr("Cannot connect: connect an output (right) to an input (left)"));
        return;
    }
    const darkroom::Endpoint from = endpoint(out), to = endpoint(in);
    darkroom::Graph trial = doc_->graph();
    freeInput(trial, to);
    std::string why;
    if (!trial.canConnect(from, to, &why)) {
        const QString text = tr("Cannot connect %1 to %2: %3")
                                 .arg(QString::fromStdString(from.str()), QString::fromStdString(to.str()),
                                      QString::fromStdString(why));
        target->setToolTip(text);
        emit message(text);
        return;
    }
    const QString err = doc_->edit(tr("Connect %1").arg(QString::fromStdString(from.str() + " -> " + to.str())),
                                   [&](darkroom::Graph& g) {
                                       freeInput(g, to);
                                       g.connect(from, to);
                                   });
    if (!err.isEmpty()) emit message(err);
}

void GraphScene::finishDetached(PortItem* target) {
    const darkroom::Edge old = *detached_;
    auto restore = [&] {
        if (auto* item = edgeItem(old)) item->setVisible(true);
    };
    if (target && !target->isOutput() && endpoint(target) == old.to) {
        restore();  // put back where it was
        return;
    }
    const QString edge = QString::fromStdString(old.from.str() + " -> " + old.to.str());
    if (!target || target->isOutput()) {
        const QString err = doc_->edit(tr("Disconnect %1").arg(edge),
                                       [&](darkroom::Graph& g) { g.disconnect(old.from, old.to); });
        if (!err.isEmpty()) {
            restore();
            emit message(err);
        }
        return;
    }
    const darkroom::Endpoint to = endpoint(target);
    darkroom::Graph trial = doc_->graph();
    trial.disconnect(old.from, old.to);
    freeInput(trial, to);
    std::string why;
    if (!trial.canConnect(old.from, to, &why)) {
        restore();
        const QString text = tr("Cannot connect %1 to %2: %3")
                                 .arg(QString::fromStdString(old.from.str()), QString::fromStdString(to.str()),
                                      QString::fromStdString(why));
        target->setToolTip(text);
        emit message(text);
        return;
    }
    const QString err = doc_->edit(tr("Move %1 to %2").arg(edge, QString::fromStdString(to.str())),
                                   [&](darkroom::Graph& g) {
                                       g.disconnect(old.from, old.to);
                                       freeInput(g, to);
                                       g.connect(old.from, to);
                                   });
    if (!err.isEmpty()) {
        restore();
        emit message(err);
    }
}

void GraphScene::commitMoves() {
    std::vector<std::pair<std::string, QPointF>> moved;
    for (auto& [name, item] : nodes_) {
        const darkroom::Node* n = doc_->graph().node(name.toStdString());
        const auto old = n ? nodePosition(*n) : std::nullopt;
        const QPointF now(qRound(item->pos().x()), qRound(item->pos().y()));
        if (n && (!old || *old != now)) moved.emplace_back(n->name, now);
    }
    if (moved.empty()) return;
    doc_->edit(moved.size() == 1 ? tr("Move %1").arg(QString::fromStdString(moved[0].first)) : tr("Move nodes"),
               [&](darkroom::Graph& g) {
                   for (const auto& [name, p] : moved) setNodePosition(g, name, p);
               });
}

void GraphScene::onParameterEdited(const QString& node, const QString& port, const darkroom::Value& v) {
    if (syncing_) return;
    const QString key = node + "." + port;
    const QString err = doc_->edit(tr("Set %1").arg(key),
                                   [&](darkroom::Graph& g) { g.setParameter(node.toStdString(), port.toStdString(), v); },
                                   QStringLiteral("set:") + key);
    if (!err.isEmpty()) {
        emit message(err);
        sync();  // puts the widget back to the value the graph holds
    }
}

void GraphScene::deleteSelection() {
    std::vector<std::string> nodes;
    std::vector<darkroom::Edge> edges;
    for (QGraphicsItem* i : selectedItems()) {
        if (i->type() == NodeItem::Type) nodes.push_back(static_cast<NodeItem*>(i)->name().toStdString());
        else if (auto* p = qgraphicsitem_cast<QGraphicsPathItem*>(i))
            edges.push_back({{p->data(0).toString().toStdString(), p->data(1).toString().toStdString()},
                             {p->data(2).toString().toStdString(), p->data(3).toString().toStdString()}});
    }
    if (nodes.empty() && edges.empty()) return;
    doc_->edit(tr("Delete"), [&](darkroom::Graph& g) {
        for (const auto& e : edges) g.disconnect(e.from, e.to);
        for (const auto& n : nodes) g.removeNode(n);
    });
}

void GraphScene::keyPressEvent(QKeyEvent* e) {
    // A focused value widget (line edit, spin box) keeps its own keys.
    if (!focusItem() && (e->key() == Qt::Key_Delete || e->key() == Qt::Key_Backspace)) {
        deleteSelection();
        e->accept();
        return;
    }
    QGraphicsScene::keyPressEvent(e);
}

}  // namespace editor
