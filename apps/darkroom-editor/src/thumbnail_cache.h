#pragma once
// Thumbnails for the explorer's grid, made off the UI thread and kept in a
// bounded cache. The grid says which items it shows (want(), most wanted
// first; it replaces the previous wish list, so a scrolled-past cell is not
// decoded), worker threads make them through a ThumbnailSource each (a
// reader is not thread-safe), and ready() says when one arrives. The cache
// holds at most `capacityBytes` of pictures, least recently used dropped.
// A new source (another database, the pipeline's output instead of the
// raw product, an edited pipeline) bumps a generation: pictures of the old
// one stay on screen, marked stale, until the new ones replace them.
#include <QImage>
#include <QObject>
#include <QString>

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <thread>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace editor {

class ThumbnailSource {
public:
    virtual ~ThumbnailSource() = default;
    // The picture of `item`, at most `size` pixels wide and high; throws
    // (darkroom::Error) with the reason when it cannot be made.
    virtual QImage make(std::size_t item, int size) = 0;
};
using ThumbnailSourceFactory = std::function<std::unique_ptr<ThumbnailSource>()>;

class ThumbnailCache : public QObject {
    Q_OBJECT
public:
    ThumbnailCache(int threads, std::size_t capacityBytes, QObject* parent = nullptr);
    ~ThumbnailCache() override;

    void setSource(ThumbnailSourceFactory factory, int size);
    int thumbnailSize() const { return size_; }
    // The picture of `item` or null; `fresh` says whether the current source
    // made it. Marks it recently used.
    const QImage* find(std::size_t item, bool* fresh = nullptr);
    // Why `item` could not be made ("" when it could, or was not tried).
    QString problem(std::size_t item) const;
    // Items to make, most wanted first; those cached fresh or being made
    // are skipped. Replaces the previous wish list.
    void want(const std::vector<std::size_t>& items);
    // Pictures made by the current source so far, and failures (tests, bench).
    int made() const { return made_; }
    int failed() const { return failed_; }
    std::size_t bytes() const { return bytes_; }
    std::size_t count() const { return entries_.size(); }
    bool idle() const;  // nothing wanted or being made

signals:
    void ready(std::size_t item);

private:
    struct Entry {
        QImage image;
        std::uint64_t generation = 0;
        std::list<std::size_t>::iterator lru;
    };
    void work();  // a worker thread's loop
    void deliver(std::size_t item, std::uint64_t generation, const QImage& image, const QString& problem);
    void evict();

    // UI thread only.
    int size_ = 96;
    std::size_t capacity_;
    std::size_t bytes_ = 0;
    std::unordered_map<std::size_t, Entry> entries_;
    std::list<std::size_t> lru_;  // most recent first
    std::unordered_map<std::size_t, QString> problems_;
    int made_ = 0, failed_ = 0;

    // Shared with the workers, under mutex_.
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<std::size_t> queue_;
    std::unordered_set<std::size_t> busy_;  // being made
    ThumbnailSourceFactory factory_;
    std::uint64_t generation_ = 0;
    int sizeShared_ = 96;
    bool stop_ = false;
    std::vector<std::thread> threads_;
};

}  // namespace editor
