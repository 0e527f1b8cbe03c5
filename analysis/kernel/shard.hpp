// A study's work split across processes (`--shard i/N`) and put back together (`steplab merge`).
//
// A study's independent work goes through study_map: call k of a study maps task i -> T_i, in
// parallel. The study's WorkLog (Workers::log, analysis/kernel/parallel.hpp; none: All) says what a
// call does:
//   All     every task runs (a study alone, the report);
//   Shard   only tasks [(i-1) n / N, i n / N) of each call run, and their results are kept in the
//           log, bytes for bytes (encode below), to be written as the shard's part;
//   Replay  no task runs: every result comes from the log, filled from the parts (merge).
// A replayed study computes everything after its calls (fits, summaries) from exactly the
// results one process would have had, so its output is the same byte for byte. A call's tasks
// must depend only on the study's input, not on another call's results (in a shard those are
// partly missing), and study_map is called from the study's own thread, in a fixed order.
#pragma once

#include <cstddef>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "analysis/kernel/kernel.hpp"
#include "analysis/kernel/parallel.hpp"

namespace steplab {

enum class WorkMode { All, Shard, Replay };

struct WorkLog {
  WorkMode mode = WorkMode::All;
  int index = 1, count = 1;  // shard index of count, 1-based
  // [call][task]: a task's result, encoded; recorded (Shard) or given (Replay)
  std::vector<std::vector<std::optional<std::string>>> calls;
  std::size_t next_call = 0;
};

// The parts do not fit the study they claim to be from (a call with another number of tasks, a
// result missing or of the wrong size).
struct PartMismatch : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The first task of shard `index` (1-based) of `count` over n tasks; shard count + 1 starts at n.
inline std::size_t shard_begin(std::size_t n, int index, int count) {
  return n * static_cast<std::size_t>(index - 1) / static_cast<std::size_t>(count);
}

// ---- results as bytes: a trivially copyable value as its bytes; vectors and strings with
// their length first; a struct with either by its own encode_fields (below). The parts are
// read back on a machine of the same kind (byte order, type sizes).

struct ByteWriter {
  std::string bytes;
  template <class T> void raw(const T& x) { bytes.append(reinterpret_cast<const char*>(&x), sizeof x); }
};
struct ByteReader {
  const std::string& bytes;
  std::size_t at = 0;
  template <class T> void raw(T& x) {
    if (at + sizeof x > bytes.size()) throw PartMismatch("a task's result is shorter than its kind");
    std::memcpy(&x, bytes.data() + at, sizeof x);
    at += sizeof x;
  }
};

template <class T> void put(ByteWriter& w, const T& x);
template <class T> void get(ByteReader& r, T& x);

template <class T> void put(ByteWriter& w, const std::vector<T>& v) {
  w.raw(v.size());
  for (const T& x : v) put(w, x);
}
template <class T> void get(ByteReader& r, std::vector<T>& v) {
  std::size_t n = 0;
  r.raw(n);
  if (n > r.bytes.size()) throw PartMismatch("a task's result holds an impossible length");
  v.resize(n);
  for (T& x : v) get(r, x);
}
template <int R> void put(ByteWriter& w, const Eigen::Matrix<double, R, 1>& v) {
  for (int i = 0; i < R; ++i) w.raw(v[i]);
}
template <int R> void get(ByteReader& r, Eigen::Matrix<double, R, 1>& v) {
  for (int i = 0; i < R; ++i) r.raw(v[i]);
}
template <int D, class F> void encode_fields(Sample<D>& s, F&& f) {
  f(s.t);
  f(s.x);
  f(s.v);
  f(s.energy);
}
inline void put(ByteWriter& w, const std::string& s) {
  w.raw(s.size());
  w.bytes += s;
}
inline void get(ByteReader& r, std::string& s) {
  std::size_t n = 0;
  r.raw(n);
  if (r.at + n > r.bytes.size()) throw PartMismatch("a task's result is shorter than its kind");
  s.assign(r.bytes, r.at, n);
  r.at += n;
}

// A struct with non-trivial members declares, next to itself,
//   template <class F> void encode_fields(T& x, F&& f) { f(x.a); f(x.b); ... }
template <class T> void put(ByteWriter& w, const T& x) {
  if constexpr (std::is_trivially_copyable_v<T>) w.raw(x);
  else encode_fields(const_cast<T&>(x), [&](auto& field) { put(w, field); });
}
template <class T> void get(ByteReader& r, T& x) {
  if constexpr (std::is_trivially_copyable_v<T>) r.raw(x);
  else encode_fields(x, [&](auto& field) { get(r, field); });
}

template <class T> std::string encode(const T& x) {
  ByteWriter w;
  put(w, x);
  return std::move(w.bytes);
}
template <class T> T decode(const std::string& bytes) {
  ByteReader r{bytes};
  T x{};
  get(r, x);
  if (r.at != bytes.size()) throw PartMismatch("a task's result is longer than its kind");
  return x;
}

// task(i) for i in [0, n) on the workers' threads (parallel.hpp), as their log says; out[i] is
// task i's result. `order` (a permutation of [0, n), or empty for 0 .. n-1) is the order in which
// the tasks start: the dearest first, so that none starts last and runs alone while the other
// threads idle. It changes no result.
template <class T, class Task>
std::vector<T> study_map(std::size_t n, const Workers& workers, Task&& task, const std::vector<std::size_t>& order = {}) {
  std::vector<T> out(n);
  WorkLog all;
  WorkLog& log = workers.log ? *workers.log : all;
  if (log.mode != WorkMode::Replay) {
    const bool shard = log.mode == WorkMode::Shard;
    const std::size_t lo = shard ? shard_begin(n, log.index, log.count) : 0;
    const std::size_t hi = shard ? shard_begin(n, log.index + 1, log.count) : n;
    std::vector<std::size_t> runs;  // the tasks this process runs, in the order they start
    for (std::size_t k = 0; k < n; ++k)
      if (const std::size_t i = order.empty() ? k : order[k]; lo <= i && i < hi) runs.push_back(i);
    const std::size_t call = shard ? log.next_call++ : 0;
    if (shard) log.calls.emplace_back(n);
    parallel_for(runs.size(), workers, [&](std::size_t k) {
      const std::size_t i = runs[k];
      out[i] = task(i);
      if (shard) log.calls[call][i] = encode(out[i]);
    });
    return out;
  }
  const std::size_t call = log.next_call++;
  if (call >= log.calls.size() || log.calls[call].size() != n)
    throw PartMismatch("the parts hold other work than this study makes (call " + std::to_string(call + 1) + ")");
  for (std::size_t i = 0; i < n; ++i) {
    if (!log.calls[call][i]) throw PartMismatch("no part holds task " + std::to_string(i) + " of call " + std::to_string(call + 1));
    out[i] = decode<T>(*log.calls[call][i]);
  }
  return out;
}

// The positions of `methods` (indices into the method table), the implicit methods' first (the
// dearest per step): a study_map order for tasks that are one method each.
inline std::vector<std::size_t> implicit_first(const std::vector<std::size_t>& methods) {
  std::vector<std::size_t> order;
  for (const bool implicit : {true, false})
    for (std::size_t k = 0; k < methods.size(); ++k)
      if (method_info(methods[k]).implicit == implicit) order.push_back(k);
  return order;
}

}  // namespace steplab
