#include "autosave.h"

#include "document.h"

#include <darkroom/atomic_file.h>
#include <darkroom/core/pipeline.h>

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>
#include <QUndoStack>

#include <algorithm>
#include <optional>
#include <csignal>
#include <cerrno>
#include <cstring>

namespace editor {

namespace {

constexpr const char* kHeader = "# darkroom-editor autosave of: ";

bool processAlive(qint64 pid) { return pid > 0 && (::kill(pid_t(pid), 0) == 0 || errno == EPERM); }

std::optional<Recovery> readRecovery(const QFileInfo& f) {
    QFile file(f.absoluteFilePath());
    if (!file.open(QIODevice::ReadOnly)) return std::nullopt;
    const QString first = QString::fromUtf8(file.readLine()).trimmed();
    Recovery r;
    r.file = f.absoluteFilePath();
    if (first.startsWith(kHeader)) r.originalPath = first.mid(int(std::strlen(kHeader)));
    r.savedAt = f.lastModified().toString("yyyy-MM-dd hh:mm:ss");
    return r;
}

}  // namespace

QString Autosave::folder() {
    return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) + "/autosave";
}

Autosave::Autosave(Document* doc, QObject* parent) : QObject(parent), doc_(doc) {
    timer_.setSingleShot(true);
    timer_.setInterval(1000);
    connect(&timer_, &QTimer::timeout, this, &Autosave::writeNow);
    connect(doc_, &Document::changed, this, [this] { timer_.start(); });
    // Saving (or undoing back to the saved state) leaves nothing to recover.
    connect(doc_->undoStack(), &QUndoStack::cleanChanged, this, [this](bool clean) {
        if (clean) discard();
    });
}

Autosave::~Autosave() = default;

void Autosave::writeNow() {
    timer_.stop();
    if (doc_->undoStack()->isClean()) {
        discard();
        return;
    }
    if (!QDir().mkpath(folder())) return;
    file_ = folder() + "/" + QString::number(QCoreApplication::applicationPid()) + ".yaml";
    const std::string text =
        kHeader + doc_->path().toStdString() + "\n" + darkroom::serializePipeline(doc_->graph());
    try {
        darkroom::writeFileAtomic(file_.toStdString(), text);
    } catch (const std::exception&) {
        // A full disk must not interrupt editing; the next edit tries again.
    }
}

void Autosave::discard() {
    timer_.stop();
    if (!file_.isEmpty()) QFile::remove(file_);
}


std::vector<Recovery> Autosave::leftBehind() {
    std::vector<Recovery> out;
    const QDir dir(folder());
    for (const QFileInfo& f : dir.entryInfoList({"*.yaml"}, QDir::Files, QDir::Time)) {
        bool ok = false;
        const qint64 pid = f.completeBaseName().toLongLong(&ok);
        if (!ok || pid == QCoreApplication::applicationPid() || processAlive(pid)) continue;
        if (auto r = readRecovery(f)) out.push_back(*r);
    }
    return out;
}

std::vector<Recovery> Autosave::setAside() {
    std::vector<Recovery> out;
    for (const QFileInfo& f : QDir(folder() + "/older").entryInfoList({"*.yaml"}, QDir::Files, QDir::Time))
        if (auto r = readRecovery(f)) out.push_back(*r);
    return out;
}

void Autosave::putAside(const Recovery& r) {
    const QString older = folder() + "/older";
    if (!QDir().mkpath(older)) return;
    // Named by when it was written, so set-aside files never collide.
    const QFileInfo f(r.file);
    QString target = older + "/" + f.lastModified().toString("yyyyMMdd-hhmmss") + "-" + f.fileName();
    for (int i = 2; QFile::exists(target); ++i)
        target = older + "/" + f.lastModified().toString("yyyyMMdd-hhmmss") + "-" + QString::number(i) + "-" + f.fileName();
    // rename() keeps the modification time, which orders the list.
    QFile::rename(r.file, target);
}

bool Autosave::restore(const Recovery& r, Document* doc, QStringList& messages) {
    QFile file(r.file);
    if (!file.open(QIODevice::ReadOnly)) {
        messages << r.file + ": cannot be read";
        return false;
    }
    const QString text = QString::fromUtf8(file.readAll());
    file.close();
    if (!doc->restore(text, r.originalPath, r.file, messages)) return false;
    QFile::remove(r.file);
    return true;
}

void Autosave::drop(const Recovery& r) { QFile::remove(r.file); }

}  // namespace editor
