// A small parallel loop over indices on std::threads (no pool is kept between calls).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The number of worker threads for a request: @p requested, or one per hardware thread if 0.
inline std::size_t workerCount(std::size_t requested)
{
    return requested > 0 ? requested : std::max<std::size_t>(1, std::thread::hardware_concurrency());
}

/// Runs body(i) for every i in [0, n) on up to @p threads threads (the caller's among them).
/// Stops handing out work after the first exception and rethrows it once all threads are done.
template <class Body>
void parallelFor(std::size_t n, std::size_t threads, Body&& body)
{
    std::atomic<std::size_t> next{0};
    std::exception_ptr failure;
    std::mutex failureMutex;
    const auto work = [&] {
        for (std::size_t i = next++; i < n; i = next++) {
            try {
                body(i);
            } catch (...) {
                std::lock_guard<std::mutex> lock(failureMutex);
                if (!failure) failure = std::current_exception();
                next = n;
            }
        }
    };
    threads = std::max<std::size_t>(1, std::min(threads, n));
    std::vector<std::thread> pool;
    for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
