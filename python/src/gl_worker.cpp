#include "gl_worker.h"

namespace raylab::python {

namespace {
std::mutex g_instanceMutex;
std::unique_ptr<GlWorker> g_instance;
} // namespace

GlWorker::GlWorker() : thread_([this] { loop(); }) {}

GlWorker::~GlWorker() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
}

void GlWorker::enqueue(std::function<void()> job) {
    {
        std::lock_guard lock(mutex_);
        jobs_.push(std::move(job));
    }
    wake_.notify_one();
}

void GlWorker::ensureContext() {
    if (context_) return;
    context_ = createHeadlessContext(GlBackend::Auto);   // RAYLAB_GL picks the backend, as for raylab-render
    state_ = std::make_unique<GlState>();
    state_->context = context_->description();
}

void GlWorker::loop() {
    for (;;) {
        std::function<void()> job;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
            if (jobs_.empty()) break;   // stopping, nothing left
            job = std::move(jobs_.front());
            jobs_.pop();
        }
        job();   // a packaged task: its exceptions travel in its future
    }
    state_.reset();     // GL objects go while their context is current
    context_.reset();
}

GlWorker& GlWorker::instance() {
    std::lock_guard lock(g_instanceMutex);
    if (!g_instance) g_instance = std::make_unique<GlWorker>();
    return *g_instance;
}

GlWorker* GlWorker::running() {
    std::lock_guard lock(g_instanceMutex);
    return g_instance.get();
}

void GlWorker::shutdown() {
    std::unique_ptr<GlWorker> worker;
    {
        std::lock_guard lock(g_instanceMutex);
        worker = std::move(g_instance);
    }
    worker.reset();
}

} // namespace raylab::python
