#pragma once
// An exclusive, non-blocking lock on a database folder, so two captures can
// never write the same database at once. Private to the cinema area.
#include <string>

namespace darkroom::cinema_detail {

class DatabaseLock {
public:
    // flock()s `<folder>/.lock` and writes our pid into it. Throws
    // darkroom::Error "database X is being written by another process (pid N)"
    // when another process holds it. A lock file left by a killed process is
    // not locked (the kernel drops flock locks with the process) and is taken over.
    explicit DatabaseLock(const std::string& folder);
    // Removes the lock file as releaseAndRemove() does.
    ~DatabaseLock();
    DatabaseLock(const DatabaseLock&) = delete;
    DatabaseLock& operator=(const DatabaseLock&) = delete;

    // Removes the lock file (while still holding the lock, so no one can
    // lock the file we are about to delete) and then unlocks.
    void releaseAndRemove();

    static constexpr const char* kFileName = ".lock";

private:
    std::string path_;
    int fd_ = -1;
};

}  // namespace darkroom::cinema_detail
