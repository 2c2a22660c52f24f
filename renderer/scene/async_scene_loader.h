#pragma once
// Loads scenes (loadScene: "builtin:NAME" or a .gltf / .glb path) on a worker thread so a window keeps drawing.
// The newest request wins: a result of an older request is dropped, and a request still waiting is replaced.
// A load in progress cannot be interrupted (the glTF loader has no cancel point); destroying the loader waits for it.
// No GL: upload the finished Scene on the GL thread.
#include "scene/scene_source.h"

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace shadowlab {

struct SceneLoadProgress {
    std::string spec;                        // the newest request
    std::string stage;                       // e.g. "loading", "waiting for an older load to finish"
    double elapsedSeconds = 0.0;             // since the request
    std::optional<std::uintmax_t> fileBytes; // size of the file (none for builtin: or a missing file)
};

struct FinishedSceneLoad {
    std::string spec;
    SceneLoadResult result;  // result.scene, or result.error naming the file and what is wrong
    double seconds = 0.0;    // from request to finish
};

class AsyncSceneLoader {
public:
    AsyncSceneLoader();
    ~AsyncSceneLoader();  // waits for a load in progress to finish
    AsyncSceneLoader(const AsyncSceneLoader&) = delete;
    AsyncSceneLoader& operator=(const AsyncSceneLoader&) = delete;

    // Starts loading `spec` (or queues it behind a load in progress); supersedes every earlier request.
    void request(const std::string& spec);

    // The newest request's result, once, when it is done; nullopt while loading or when nothing was requested.
    std::optional<FinishedSceneLoad> poll();

    // While the newest request is not yet finished; nullopt otherwise.
    std::optional<SceneLoadProgress> progress() const;
    bool busy() const { return progress().has_value(); }

    // Runs on the loader's thread each time a result becomes ready to poll (a window host wakes its event loop with
    // it instead of polling on a timer). Set it before the first request.
    void setFinishedCallback(std::function<void()> finished);

private:
    using Clock = std::chrono::steady_clock;
    struct Request {
        std::uint64_t id = 0;
        std::string spec;
        Clock::time_point requested;
        std::optional<std::uintmax_t> fileBytes;
    };
    void work();

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<Request> waiting_;    // requested, not yet started
    std::optional<Request> loading_;    // being loaded by the worker
    std::optional<FinishedSceneLoad> finished_;  // the newest request's result, not yet polled
    std::uint64_t newestId_ = 0;
    bool stopping_ = false;
    std::function<void()> finishedCallback_;
    std::thread worker_;
};

}  // namespace shadowlab
