#include "palette.h"

#include <QHeaderView>
#include <QLineEdit>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <map>

namespace editor {

Palette::Palette(const darkroom::Registry& registry, QWidget* parent) : QWidget(parent) {
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(4, 4, 4, 4);
    search_ = new QLineEdit;
    search_->setPlaceholderText(tr("Search filters (Enter adds)"));
    search_->setClearButtonEnabled(true);
    tree_ = new QTreeWidget;
    tree_->setHeaderHidden(true);
    lay->addWidget(search_);
    lay->addWidget(tree_, 1);
    std::map<QString, QTreeWidgetItem*> groups;
    for (const auto* f : registry.filters()) {
        const QString cat = f->info.category.empty() ? tr("Other") : QString::fromStdString(f->info.category);
        auto*& g = groups[cat];
        if (!g) {
            g = new QTreeWidgetItem(tree_, {cat});
            g->setFlags(Qt::ItemIsEnabled);
        }
        auto* item = new QTreeWidgetItem(g, {QString::fromStdString(f->info.type)});
        item->setToolTip(0, QString::fromStdString(f->info.doc + "\n(" + f->origin.plugin + " " + f->origin.version + ")"));
        item->setData(0, Qt::UserRole, QString::fromStdString(f->info.type));
    }
    tree_->sortItems(0, Qt::AscendingOrder);
    tree_->expandAll();
    connect(search_, &QLineEdit::textChanged, this, &Palette::filter);
    connect(search_, &QLineEdit::returnPressed, this, [this] {
        for (int i = 0; i < tree_->topLevelItemCount(); ++i)
            for (int j = 0; j < tree_->topLevelItem(i)->childCount(); ++j) {
                auto* c = tree_->topLevelItem(i)->child(j);
                if (!c->isHidden()) {
                    emit addRequested(c->data(0, Qt::UserRole).toString());
                    search_->clear();
                    return;
                }
            }
    });
    connect(tree_, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
        const QString type = item->data(0, Qt::UserRole).toString();
        if (!type.isEmpty()) emit addRequested(type);
    });
}

void Palette::focusSearch() {
    search_->setFocus();
    search_->selectAll();
}

void Palette::filter(const QString& text) {
    for (int i = 0; i < tree_->topLevelItemCount(); ++i) {
        auto* g = tree_->topLevelItem(i);
        bool any = false;
        for (int j = 0; j < g->childCount(); ++j) {
            auto* c = g->child(j);
            const bool show = c->text(0).contains(text, Qt::CaseInsensitive) ||
                              g->text(0).contains(text, Qt::CaseInsensitive);
            c->setHidden(!show);
            any = any || show;
        }
        g->setHidden(!any);
    }
}

}  // namespace editor
