#pragma once
// The one thread that owns the Python module's OpenGL context. A GL context is current on one
// thread at a time, while Python may call from any thread: every GL job runs here, in order, and
// the caller waits for it with the GIL released (so other Python threads run meanwhile).
#include "gl/gl_context.h"
#include "gl_state.h"

#include <condition_variable>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <queue>
#include <thread>

namespace raylab::python {

class GlWorker {
public:
    // Starts the thread; the context is made there on the first job (RAYLAB_GL picks the backend,
    // as for raylab-render: auto, osmesa or egl).
    GlWorker();
    ~GlWorker();   // finishes queued jobs, destroys the context on its thread
    GlWorker(const GlWorker&) = delete;
    GlWorker& operator=(const GlWorker&) = delete;

    // Queues job(GlState&), run with the context current; the future carries its result or its
    // exception (also the context's own failure to start, which the next job tries again).
    template <class F>
    auto post(F job) -> std::future<decltype(job(std::declval<GlState&>()))> {
        using R = decltype(job(std::declval<GlState&>()));
        auto task = std::make_shared<std::packaged_task<R()>>([this, job = std::move(job)]() mutable -> R {
            ensureContext();
            return job(*state_);
        });
        auto future = task->get_future();
        enqueue([task] { (*task)(); });
        return future;
    }

    // The module's worker, started on first use. shutdown() (registered with atexit) joins it
    // before the interpreter tears down.
    static GlWorker& instance();
    static GlWorker* running();   // the worker if started and not shut down, else null
    static void shutdown();

private:
    void enqueue(std::function<void()> job);
    void loop();
    void ensureContext();

    std::mutex mutex_;
    std::condition_variable wake_;
    std::queue<std::function<void()>> jobs_;
    bool stopping_ = false;
    std::unique_ptr<GlContext> context_;   // context_ and state_: touched on the worker thread only
    std::unique_ptr<GlState> state_;
    std::thread thread_;
};

} // namespace raylab::python
