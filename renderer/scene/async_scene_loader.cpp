#include "scene/async_scene_loader.h"

#include <filesystem>

namespace shadowlab {

namespace {

std::optional<std::uintmax_t> fileSize(const std::string& spec) {
    if (spec.rfind(kBuiltinPrefix, 0) == 0) return std::nullopt;
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(spec, ec);
    if (ec) return std::nullopt;
    return size;
}

}  // namespace

AsyncSceneLoader::AsyncSceneLoader() : worker_([this] { work(); }) {}

AsyncSceneLoader::~AsyncSceneLoader() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
        waiting_.reset();
    }
    wake_.notify_all();
    worker_.join();
}

void AsyncSceneLoader::request(const std::string& spec) {
    Request next{0, spec, Clock::now(), fileSize(spec)};  // stat outside the lock
    {
        std::lock_guard lock(mutex_);
        next.id = ++newestId_;
        waiting_ = std::move(next);  // replaces an older request that had not started
        finished_.reset();           // an unpolled older result is stale now
    }
    wake_.notify_all();
}

void AsyncSceneLoader::setFinishedCallback(std::function<void()> finished) {
    std::lock_guard lock(mutex_);
    finishedCallback_ = std::move(finished);
}

std::optional<FinishedSceneLoad> AsyncSceneLoader::poll() {
    std::lock_guard lock(mutex_);
    std::optional<FinishedSceneLoad> out = std::move(finished_);
    finished_.reset();
    return out;
}

std::optional<SceneLoadProgress> AsyncSceneLoader::progress() const {
    std::lock_guard lock(mutex_);
    const Request* newest = waiting_ ? &*waiting_ : (loading_ && loading_->id == newestId_ ? &*loading_ : nullptr);
    if (!newest) return std::nullopt;
    SceneLoadProgress p;
    p.spec = newest->spec;
    p.fileBytes = newest->fileBytes;
    p.elapsedSeconds = std::chrono::duration<double>(Clock::now() - newest->requested).count();
    if (loading_ && newest == &*loading_) p.stage = "loading";
    else if (loading_) p.stage = "waiting for an older load to finish (it cannot be interrupted)";
    else p.stage = "starting";
    return p;
}

void AsyncSceneLoader::work() {
    std::unique_lock lock(mutex_);
    while (true) {
        wake_.wait(lock, [this] { return stopping_ || waiting_.has_value(); });
        if (stopping_) return;
        loading_ = std::move(waiting_);
        waiting_.reset();
        const std::string spec = loading_->spec;
        lock.unlock();
        SceneLoadResult result = loadScene(spec);
        lock.lock();
        // Only the newest request's result is kept; an older one finishing late is dropped.
        const bool newest = loading_->id == newestId_;
        if (newest) {
            const double seconds = std::chrono::duration<double>(Clock::now() - loading_->requested).count();
            finished_ = FinishedSceneLoad{spec, std::move(result), seconds};
        }
        loading_.reset();
        if (newest && finishedCallback_) {
            const std::function<void()> finished = finishedCallback_;
            lock.unlock();  // the callback may take the host's locks
            finished();
            lock.lock();
        }
    }
}

}  // namespace shadowlab
