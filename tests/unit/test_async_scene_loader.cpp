// Loading scenes off the UI thread: a finished Scene or a clear error arrives through poll(), progress is visible
// while loading, the newest request wins, and destroying the loader mid-load is safe.
#include "scene/async_scene_loader.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <thread>

using namespace shadowlab;
using namespace std::chrono_literals;

namespace {

const std::string kFlightHelmet = std::string(SHADOWLAB_SHARED_SCENES) + "/FlightHelmet_geometry/FlightHelmet.gltf";
const std::string kBrokenGltf = "/usr/share/assimp/models/glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf";

// Polls like an editor frame loop would, until a result arrives (or a generous time limit passes).
std::optional<FinishedSceneLoad> waitForResult(AsyncSceneLoader& loader) {
    for (auto start = std::chrono::steady_clock::now(); std::chrono::steady_clock::now() - start < 60s;) {
        if (auto finished = loader.poll()) return finished;
        std::this_thread::sleep_for(2ms);
    }
    return std::nullopt;
}

}  // namespace

TEST(AsyncSceneLoader, DeliversTheSceneOnceAndThenIsIdle) {
    AsyncSceneLoader loader;
    EXPECT_FALSE(loader.poll().has_value());
    EXPECT_FALSE(loader.busy());
    loader.request("builtin:textbook");
    std::optional<FinishedSceneLoad> done = waitForResult(loader);
    ASSERT_TRUE(done.has_value());
    EXPECT_EQ(done->spec, "builtin:textbook");
    ASSERT_TRUE(done->result.ok()) << done->result.error;
    EXPECT_FALSE(done->result.scene->meshes.empty());
    EXPECT_GE(done->seconds, 0.0);
    EXPECT_FALSE(loader.poll().has_value());  // delivered once
    EXPECT_FALSE(loader.busy());
}

// A window host sleeps until an event: the loader's finished callback is that event. It runs once a result is ready
// to poll, once per delivered result, so a sleeping host needs no timer to notice a load.
TEST(AsyncSceneLoader, TheFinishedCallbackRunsOnceAResultIsReadyToPoll) {
    std::mutex mutex;
    std::condition_variable signal;
    int calls = 0;
    bool readyWhenCalled = true;
    AsyncSceneLoader loader;
    loader.setFinishedCallback([&] {
        std::lock_guard<std::mutex> lock(mutex);
        ++calls;
        readyWhenCalled = readyWhenCalled && !loader.busy();
        signal.notify_all();
    });
    loader.request("builtin:textbook");
    {
        std::unique_lock<std::mutex> lock(mutex);
        ASSERT_TRUE(signal.wait_for(lock, 600s, [&] { return calls > 0; }))
            << "no finished callback in 600 s for builtin:textbook";
    }
    EXPECT_TRUE(readyWhenCalled) << "the callback ran before the result was ready";
    std::optional<FinishedSceneLoad> done = loader.poll();
    ASSERT_TRUE(done.has_value()) << "the callback ran, but poll() had no result";
    EXPECT_EQ(done->spec, "builtin:textbook");
    std::lock_guard<std::mutex> lock(mutex);
    EXPECT_EQ(calls, 1);
}

TEST(AsyncSceneLoader, BrokenAndMissingFilesGiveAClearError) {
    if (!std::filesystem::exists(kBrokenGltf)) GTEST_SKIP() << "assimp-testmodels not installed";
    AsyncSceneLoader loader;
    loader.request(kBrokenGltf);
    std::optional<FinishedSceneLoad> broken = waitForResult(loader);
    ASSERT_TRUE(broken.has_value());
    EXPECT_FALSE(broken->result.ok());
    EXPECT_NE(broken->result.error.find("AllIndicesOutOfRange.gltf"), std::string::npos) << broken->result.error;
    EXPECT_NE(broken->result.error.find("out of range"), std::string::npos) << broken->result.error;

    loader.request("/nonexistent/scene.glb");
    std::optional<FinishedSceneLoad> missing = waitForResult(loader);
    ASSERT_TRUE(missing.has_value());
    EXPECT_FALSE(missing->result.ok());
    EXPECT_NE(missing->result.error.find("/nonexistent/scene.glb"), std::string::npos) << missing->result.error;
}

TEST(AsyncSceneLoader, ProgressShowsTheNewestRequestItsFileSizeAndElapsedTime) {
    if (!std::filesystem::exists(kFlightHelmet)) GTEST_SKIP() << "shared scenes missing";
    AsyncSceneLoader loader;
    loader.request(kFlightHelmet);
    std::optional<SceneLoadProgress> progress = loader.progress();
    ASSERT_TRUE(progress.has_value());  // nothing can have finished yet: poll() was not called
    EXPECT_EQ(progress->spec, kFlightHelmet);
    ASSERT_TRUE(progress->fileBytes.has_value());
    EXPECT_EQ(*progress->fileBytes, std::filesystem::file_size(kFlightHelmet));
    EXPECT_FALSE(progress->stage.empty());
    std::this_thread::sleep_for(20ms);
    if (auto later = loader.progress()) EXPECT_GE(later->elapsedSeconds, 0.015);
    std::optional<FinishedSceneLoad> done = waitForResult(loader);
    ASSERT_TRUE(done.has_value());
    EXPECT_TRUE(done->result.ok()) << done->result.error;
    EXPECT_FALSE(loader.progress().has_value());
}

TEST(AsyncSceneLoader, TheNewestRequestWinsAndOlderResultsAreDropped) {
    if (!std::filesystem::exists(kFlightHelmet)) GTEST_SKIP() << "shared scenes missing";
    AsyncSceneLoader loader;
    loader.request(kFlightHelmet);
    // Wait until the worker is inside the big load, then ask for something else.
    for (auto start = std::chrono::steady_clock::now(); std::chrono::steady_clock::now() - start < 10s;) {
        auto p = loader.progress();
        if (!p || p->stage == "loading") break;
        std::this_thread::sleep_for(1ms);
    }
    loader.request("builtin:grazing");  // replaced before it starts
    loader.request("builtin:fence");
    auto progress = loader.progress();
    ASSERT_TRUE(progress.has_value());
    EXPECT_EQ(progress->spec, "builtin:fence");

    std::optional<FinishedSceneLoad> done = waitForResult(loader);
    ASSERT_TRUE(done.has_value());
    EXPECT_EQ(done->spec, "builtin:fence");
    ASSERT_TRUE(done->result.ok()) << done->result.error;
    // Neither FlightHelmet nor grazing shows up afterwards.
    std::this_thread::sleep_for(50ms);
    EXPECT_FALSE(loader.poll().has_value());
    EXPECT_FALSE(loader.busy());
}

TEST(AsyncSceneLoader, DestroyingWhileLoadingWaitsForTheWorker) {
    if (!std::filesystem::exists(kFlightHelmet)) GTEST_SKIP() << "shared scenes missing";
    for (int i = 0; i < 3; ++i) {
        auto loader = std::make_unique<AsyncSceneLoader>();
        loader->request(kFlightHelmet);
        loader->request("builtin:textbook");
        std::this_thread::sleep_for(std::chrono::milliseconds(i * 5));
        loader.reset();  // must neither crash nor hang (a dangling worker would touch freed memory)
    }
}
