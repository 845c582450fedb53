#pragma once
// "Newest job wins": CPU work on worker threads whose result matters only while no newer job has
// started. start() supersedes the job in flight (its ticket is cancelled, which the work may poll to
// stop early) and only the newest job's result or error is delivered, on the owner's thread, through
// a queued call. The destructor cancels and waits for the workers, so no job outlives its owner.
// The file loader, the GPU-scene preparer and the click picker's own jobs all run this way.
#include <QMetaObject>
#include <QObject>
#include <QString>
#include <QThreadPool>

#include <atomic>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

namespace glint::editor {

// One job's cancel flag, shared with its work.
struct JobTicket {
    std::atomic<bool> cancelled{false};
};
using Ticket = std::shared_ptr<JobTicket>;

template <class Result>
class LatestJob {
public:
    // On a worker; throws to fail. It may poll ticket->cancelled and post() progress with the ticket.
    using Work = std::function<Result(const Ticket&)>;
    using Done = std::function<void(Result)>;        // on the owner's thread, newest job only
    using Failed = std::function<void(const QString&)>;

    // `threads` > 1 lets a new job start while a cancelled one that cannot stop runs on to its end.
    LatestJob(QObject* owner, int threads) : owner_(owner) { pool_.setMaxThreadCount(threads); }
    ~LatestJob() {
        cancel();
        pool_.waitForDone();
    }
    LatestJob(const LatestJob&) = delete;
    LatestJob& operator=(const LatestJob&) = delete;

    Ticket start(Work work, Done done, Failed failed = {}) {
        cancel();
        auto ticket = std::make_shared<JobTicket>();
        current_ = ticket;
        pool_.start([this, ticket, work = std::move(work), done = std::move(done), failed = std::move(failed)] {
            if (ticket->cancelled) return; // superseded while it waited for a worker
            auto result = std::make_shared<std::optional<Result>>();
            QString error;
            try {
                result->emplace(work(ticket));
            } catch (const std::exception& e) {
                error = QString::fromStdString(e.what());
            } catch (...) { // a cancelled job's own stop signal, or a foreign exception
                error = QStringLiteral("unexpected error");
            }
            if (ticket->cancelled) return; // dropped here, on the worker
            QMetaObject::invokeMethod(owner_, [this, ticket, result, error, done, failed] {
                if (ticket != current_) return; // superseded after it finished
                current_.reset();
                if (result->has_value()) done(std::move(**result));
                else if (failed) failed(error);
            }, Qt::QueuedConnection);
        });
        return ticket;
    }

    // Drops the job in flight: its result never arrives.
    void cancel() {
        if (current_) current_->cancelled = true;
        current_.reset();
    }

    // Runs `f` on the owner's thread while `ticket` is the newest job (progress from the work).
    void post(const Ticket& ticket, std::function<void()> f) {
        QMetaObject::invokeMethod(owner_, [this, ticket, f = std::move(f)] {
            if (ticket == current_) f();
        }, Qt::QueuedConnection);
    }

    bool busy() const { return current_ != nullptr; }
    int running() const { return pool_.activeThreadCount(); } // cancelled jobs still running included

private:
    QObject* owner_;
    QThreadPool pool_;
    Ticket current_;
};

} // namespace glint::editor
