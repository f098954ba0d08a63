#include "quick_add.h"

#include <QKeyEvent>
#include <QLineEdit>
#include <QListWidget>
#include <QScreen>
#include <QVBoxLayout>

namespace editor {

QuickAdd::QuickAdd(const darkroom::Registry& registry, QWidget* parent) : QFrame(parent, Qt::Popup) {
    setFrameShape(QFrame::StyledPanel);
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(4, 4, 4, 4);
    search_ = new QLineEdit;
    search_->setPlaceholderText(tr("Add node…"));
    list_ = new QListWidget;
    lay->addWidget(search_);
    lay->addWidget(list_);
    for (const auto* f : registry.filters()) {
        const QString type = QString::fromStdString(f->info.type);
        const QString cat = QString::fromStdString(f->info.category);
        auto* item = new QListWidgetItem(cat.isEmpty() ? type : type + QStringLiteral("   ") + cat, list_);
        item->setData(Qt::UserRole, type);
        item->setData(Qt::UserRole + 1, cat);
        item->setToolTip(QString::fromStdString(f->info.doc));
    }
    list_->sortItems();
    resize(300, 360);
    search_->installEventFilter(this);
    connect(search_, &QLineEdit::textChanged, this, &QuickAdd::filter);
    connect(search_, &QLineEdit::returnPressed, this, &QuickAdd::choose);
    connect(list_, &QListWidget::itemActivated, this, &QuickAdd::choose);
    connect(list_, &QListWidget::itemClicked, this, &QuickAdd::choose);
}

void QuickAdd::popup(QPoint globalPos) {
    search_->clear();
    filter({});
    QPoint at = globalPos;
    if (const QScreen* s = screen()) {  // keep it on the screen
        const QRect avail = s->availableGeometry();
        at.setX(std::min(at.x(), avail.right() - width()));
        at.setY(std::min(at.y(), avail.bottom() - height()));
    }
    move(at);
    show();
    search_->setFocus(Qt::PopupFocusReason);
}

void QuickAdd::filter(const QString& text) {
    QListWidgetItem* first = nullptr;
    for (int i = 0; i < list_->count(); ++i) {
        auto* item = list_->item(i);
        const bool show = item->data(Qt::UserRole).toString().contains(text, Qt::CaseInsensitive) ||
                          item->data(Qt::UserRole + 1).toString().contains(text, Qt::CaseInsensitive);
        item->setHidden(!show);
        if (show && !first) first = item;
    }
    list_->setCurrentItem(first);
}

void QuickAdd::choose() {
    QListWidgetItem* item = list_->currentItem();
    if (!item || item->isHidden()) return;
    const QString type = item->data(Qt::UserRole).toString();
    hide();
    emit chosen(type);
}

bool QuickAdd::eventFilter(QObject* watched, QEvent* e) {
    // Up and Down in the search field move through the list.
    if (watched == search_ && e->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent*>(e)->key();
        if (key == Qt::Key_Up || key == Qt::Key_Down) {
            int row = list_->currentRow();
            do {
                row += key == Qt::Key_Down ? 1 : -1;
            } while (row >= 0 && row < list_->count() && list_->item(row)->isHidden());
            if (row >= 0 && row < list_->count()) list_->setCurrentRow(row);
            return true;
        }
        if (key == Qt::Key_Escape) {
            hide();
            return true;
        }
    }
    return QFrame::eventFilter(watched, e);
}

}  // namespace editor
