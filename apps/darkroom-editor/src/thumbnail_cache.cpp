#include "thumbnail_cache.h"

#include <QCoreApplication>
#include <QMetaObject>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace editor {

ThumbnailCache::ThumbnailCache(int threads, std::size_t capacityBytes, QObject* parent)
    : QObject(parent), capacity_(capacityBytes) {
    for (int i = 0; i < std::max(1, threads); ++i) threads_.emplace_back([this] { work(); });
}

ThumbnailCache::~ThumbnailCache() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
        queue_.clear();
    }
    wake_.notify_all();
    for (auto& t : threads_) t.join();
}

void ThumbnailCache::setSource(ThumbnailSourceFactory factory, int size) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        factory_ = std::move(factory);
        ++generation_;
        sizeShared_ = size;
        queue_.clear();
    }
    size_ = size;
    problems_.clear();
    made_ = failed_ = 0;
}

const QImage* ThumbnailCache::find(std::size_t item, bool* fresh) {
    const auto it = entries_.find(item);
    if (it == entries_.end()) return nullptr;
    lru_.splice(lru_.begin(), lru_, it->second.lru);
    if (fresh) *fresh = it->second.generation == generation_;  // written on this thread only
    return &it->second.image;
}

QString ThumbnailCache::problem(std::size_t item) const {
    const auto it = problems_.find(item);
    return it == problems_.end() ? QString() : it->second;
}

void ThumbnailCache::want(const std::vector<std::size_t>& items) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        queue_.clear();
        for (std::size_t item : items) {
            const auto it = entries_.find(item);
            if (it != entries_.end() && it->second.generation == generation_) continue;
            if (busy_.count(item) || problems_.count(item)) continue;
            queue_.push_back(item);
        }
        if (queue_.empty()) return;
    }
    wake_.notify_all();
}

bool ThumbnailCache::idle() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return queue_.empty() && busy_.empty();
}

void ThumbnailCache::work() {
    // Behind the interface: a frame of the window (painting, brushing,
    // the live evaluation) goes first when the cores are busy.
    setpriority(PRIO_PROCESS, pid_t(syscall(SYS_gettid)), 5);
    std::unique_ptr<ThumbnailSource> source;
    std::uint64_t sourceGeneration = 0;
    for (;;) {
        std::size_t item = 0;
        std::uint64_t generation = 0;
        int size = 0;
        ThumbnailSourceFactory factory;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [this] { return stop_ || !queue_.empty(); });
            if (stop_) return;
            item = queue_.front();
            queue_.pop_front();
            busy_.insert(item);
            generation = generation_;
            size = sizeShared_;
            if (sourceGeneration != generation) factory = factory_;
        }
        QImage image;
        QString problem;
        try {
            if (factory) {  // the source changed: this thread's own reader for it
                source = factory();
                sourceGeneration = generation;
            }
            if (source) image = source->make(item, size);
        } catch (const std::exception& e) {
            problem = QString::fromStdString(e.what());
        }
        if (image.isNull() && problem.isEmpty()) problem = tr("nothing to show");
        // Delivered on the UI thread, which owns the cache; dropped if the
        // cache is gone by then (the destructor joins this thread first).
        QMetaObject::invokeMethod(this, [this, item, generation, image, problem] {
            deliver(item, generation, image, problem);
        }, Qt::QueuedConnection);
    }
}

void ThumbnailCache::deliver(std::size_t item, std::uint64_t generation, const QImage& image, const QString& problem) {
    bool current;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        busy_.erase(item);
        current = generation == generation_;
    }
    if (!current) return;
    if (!problem.isEmpty()) {
        problems_[item] = problem;
        ++failed_;
        emit ready(item);
        return;
    }
    auto it = entries_.find(item);
    if (it != entries_.end()) {
        bytes_ -= std::size_t(it->second.image.sizeInBytes());
        it->second.image = image;
        it->second.generation = generation;
        lru_.splice(lru_.begin(), lru_, it->second.lru);
    } else {
        lru_.push_front(item);
        entries_.emplace(item, Entry{image, generation, lru_.begin()});
    }
    bytes_ += std::size_t(image.sizeInBytes());
    ++made_;
    evict();
    emit ready(item);
}

void ThumbnailCache::evict() {
    while (bytes_ > capacity_ && lru_.size() > 1) {
        const std::size_t victim = lru_.back();
        lru_.pop_back();
        const auto it = entries_.find(victim);
        bytes_ -= std::size_t(it->second.image.sizeInBytes());
        entries_.erase(it);
    }
}

}  // namespace editor
