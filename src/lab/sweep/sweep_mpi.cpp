// The sweep across MPI ranks: rank 0 owns the sweep folder and hands out points one request at a
// time (dynamic load balancing: a rank that finishes early asks again), while every rank,
// rank 0 included, runs points on its own worker threads. Results travel to rank 0 as the text
// of their point files, which rank 0 writes as they arrive, so an MPI sweep resumes like a local
// one and its final files are the same bytes.
//
// Only each rank's main thread calls MPI (MPI_THREAD_FUNNELED). Waits poll MPI_Test/MPI_Iprobe
// with a short sleep instead of blocking in MPI: Open MPI's blocking calls spin a core, which
// the workers need.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <deque>
#include <thread>

#include <fmt/format.h>

#include "lab/sweep/sweep_pool.hpp"
#include "lab/sweep/sweep_run.hpp"

namespace fl {
namespace {

constexpr int kTagRequest = 1;  // rank > 0 -> 0: {"results": [...], "want": n, "finished": bool}
constexpr int kTagReply = 2;    // 0 -> rank: {"points": [...], "exhausted": bool}
constexpr auto kPoll = std::chrono::milliseconds(2);

class MpiSession {
 public:
  MpiSession() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
    MPI_Comm_size(node, &node_size_);
    MPI_Comm_free(&node);
  }
  ~MpiSession() { MPI_Finalize(); }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  int node_size() const { return node_size_; }

 private:
  int rank_ = 0;
  int size_ = 1;
  int node_size_ = 1;
};

void send_text(const std::string& text, int destination, int tag) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, destination, tag, MPI_COMM_WORLD);
}

// A waiting message with `tag` (from any rank), received; nullopt if there is none yet.
std::optional<std::pair<int, std::string>> try_receive(int source, int tag) {
  int flag = 0;
  MPI_Status status;
  MPI_Iprobe(source, tag, MPI_COMM_WORLD, &flag, &status);
  if (flag == 0) return std::nullopt;
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  std::string text(static_cast<std::size_t>(count), '\0');
  MPI_Recv(text.data(), count, MPI_CHAR, status.MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return std::make_pair(status.MPI_SOURCE, std::move(text));
}

std::string receive(int source, int tag) {
  while (true) {
    if (auto m = try_receive(source, tag)) return std::move(m->second);
    std::this_thread::sleep_for(kPoll);
  }
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

SweepOutcome run_root(const SweepSpec& spec, const SweepRunOptions& options,
                      const SweepStore& store, const MpiSession& mpi, int threads,
                      std::chrono::steady_clock::time_point start) {
  const std::size_t count = spec.point_count();
  const auto done = store.load_points();
  const std::vector<std::size_t> pending = pending_points(count, options.shard, done);
  SweepOutcome outcome;
  outcome.points = count;
  for (std::size_t i = 0; i < count; ++i)
    if (!options.shard || options.shard->contains(i)) ++outcome.selected;
  outcome.resumed = outcome.selected - pending.size();
  outcome.workers = threads;
  outcome.ranks = mpi.size();

  SweepProgress progress;
  progress.total = outcome.selected;
  progress.resumed = outcome.resumed;
  progress.done = outcome.resumed;
  double wall_sum = 0.0;
  outcome.ran_by_rank.assign(static_cast<std::size_t>(mpi.size()), 0);
  const auto account = [&](const PointResult& r, int rank) {
    ++outcome.ran_by_rank[static_cast<std::size_t>(rank)];
    ++outcome.ran;
    ++progress.done;
    wall_sum += r.wall_s;
    count_no_result(r.row, progress);
  };

  std::deque<std::size_t> queue(pending.begin(), pending.end());
  const auto next_point = [&]() -> std::optional<std::size_t> {
    if (progress.stopping || queue.empty()) return std::nullopt;
    const std::size_t i = queue.front();
    queue.pop_front();
    return i;
  };
  WorkPool<PointResult> pool(threads, [&](std::size_t index) {
    PointResult r = run_sweep_point(spec, sweep_point(spec, index), options.inputs);
    store.save_point(r);
    return r;
  });
  bool pool_closed = false;
  int finished_ranks = 0;
  auto last_report = start;
  while (true) {
    if (options.stop != nullptr && options.stop->load() && !progress.stopping) {
      progress.stopping = true;
      pool.drop_queued();
    }
    // Rank 0's own workers take points only as they become free, so the others get their share.
    while (!pool_closed && pool.busy() < static_cast<std::size_t>(threads)) {
      const auto p = next_point();
      if (!p) break;
      pool.push(*p);
    }
    if (!pool_closed && (queue.empty() || progress.stopping)) {
      pool.close();
      pool_closed = true;
    }
    bool heard = false;
    while (auto message = try_receive(MPI_ANY_SOURCE, kTagRequest)) {
      heard = true;
      const nlohmann::json request = nlohmann::json::parse(message->second);
      for (const nlohmann::json& text : request.at("results")) {
        const auto r = parse_point_file(text.get<std::string>(), store.digest());
        if (!r)
          throw std::runtime_error("rank " + std::to_string(message->first) +
                                   " sent a result of another plan");
        store.save_point(*r);
        account(*r, message->first);
      }
      nlohmann::json reply{{"points", nlohmann::json::array()}};
      for (int k = 0; k < request.at("want").get<int>(); ++k) {
        const auto p = next_point();
        if (!p) break;
        reply["points"].push_back(*p);
      }
      reply["exhausted"] = queue.empty() || progress.stopping;
      if (request.at("finished").get<bool>()) ++finished_ranks;
      send_text(reply.dump(), message->first, kTagReply);
    }
    if (pool.finished()) {
      if (finished_ranks == mpi.size() - 1) break;
      if (!heard) std::this_thread::sleep_for(kPoll);
    } else {
      for (const PointResult& r : pool.take(kPoll)) {
        account(r, 0);
        heard = true;
      }
    }
    const auto now = std::chrono::steady_clock::now();
    if (options.progress && (heard || now - last_report > std::chrono::milliseconds(250))) {
      progress.elapsed_s = seconds_since(start);
      options.progress(progress);
      last_report = now;
    }
  }
  progress.elapsed_s = seconds_since(start);
  if (options.progress) options.progress(progress);
  outcome.interrupted = outcome.ran < pending.size();
  outcome.wall_s = seconds_since(start);
  finish_sweep(store, outcome, wall_sum);
  return outcome;
}

void run_worker(const SweepSpec& spec, const SweepRunOptions& options, const std::string& digest,
                int threads) {
  WorkPool<PointResult> pool(threads, [&](std::size_t index) {
    return run_sweep_point(spec, sweep_point(spec, index), options.inputs);
  });
  bool exhausted = false;
  std::vector<std::string> outbox;
  while (true) {
    const std::size_t busy = pool.busy();
    const std::size_t idle =
        exhausted ? 0 : static_cast<std::size_t>(threads) - std::min<std::size_t>(threads, busy);
    // Wait for a result unless there is room to ask for work now.
    const auto wait = idle > 0 || (exhausted && pool.finished()) ? std::chrono::milliseconds(0)
                                                                 : std::chrono::milliseconds(250);
    for (const PointResult& r : pool.take(wait)) outbox.push_back(point_file_text(r, digest));
    if (options.stop != nullptr && options.stop->load() && !exhausted) {
      exhausted = true;
      pool.drop_queued();
      pool.close();
    }
    const bool finished = exhausted && pool.finished();
    const std::size_t want =
        exhausted ? 0
                  : static_cast<std::size_t>(threads) - std::min<std::size_t>(threads, pool.busy());
    if (outbox.empty() && want == 0 && !finished) continue;
    const nlohmann::json request{{"results", outbox}, {"want", want}, {"finished", finished}};
    outbox.clear();
    send_text(request.dump(), 0, kTagRequest);
    const nlohmann::json reply = nlohmann::json::parse(receive(0, kTagReply));
    for (const nlohmann::json& p : reply.at("points")) pool.push(p.get<std::size_t>());
    if (finished) break;
    if (reply.at("exhausted").get<bool>() && !exhausted) {
      exhausted = true;
      pool.close();
    }
  }
}

}  // namespace

bool sweep_has_mpi() {
  return true;
}

SweepOutcome run_sweep_mpi(const SweepSpec& spec, const SweepRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  MpiSession mpi;
  const int threads =
      options.workers > 0 ? options.workers : std::max(1, hardware_workers() / mpi.node_size());
  const nlohmann::json plan = sweep_plan(spec);
  const std::string digest = text_digest(plan.dump());

  // Rank 0 opens the folder; every rank learns whether it could, and checks it read the same plan.
  std::optional<SweepStore> store;
  std::string refusal;
  if (mpi.rank() == 0) {
    try {
      store.emplace(SweepStore::create(options.out_dir, plan, options.fresh));
    } catch (const std::exception& e) {
      refusal = e.what();
    }
  }
  char root_digest[17] = {};
  int refused = refusal.empty() ? 0 : 1;
  if (mpi.rank() == 0) fmt::format_to_n(root_digest, 16, "{}", digest);
  MPI_Bcast(&refused, 1, MPI_INT, 0, MPI_COMM_WORLD);
  MPI_Bcast(root_digest, 17, MPI_CHAR, 0, MPI_COMM_WORLD);
  if (refused != 0)
    throw InputError(SourceLocation{},
                     mpi.rank() == 0 ? refusal : "rank 0 could not open the sweep folder");
  int same = digest == std::string(root_digest, 16) ? 1 : 0;
  int all_same = 0;
  MPI_Allreduce(&same, &all_same, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (all_same == 0)
    throw InputError(SourceLocation{spec.file, 0, 0},
                     "the MPI ranks read different sweeps (is the sweep file or its scene the "
                     "same on every node?)");

  try {
    if (mpi.rank() == 0) return run_root(spec, options, *store, mpi, threads, start);
    run_worker(spec, options, digest, threads);
  } catch (const std::exception& e) {
    // A rank that fails mid-sweep would leave the others waiting: stop them all. The points
    // written so far stay, and the sweep resumes from them.
    std::fprintf(stderr, "frictionlab sweep (rank %d): error: %s\n", mpi.rank(), e.what());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, dynamic_cast<const InputError*>(&e) != nullptr ? 2 : 1);
  }
  SweepOutcome outcome;
  outcome.root = false;
  outcome.ranks = mpi.size();
  outcome.workers = threads;
  return outcome;
}

}  // namespace fl
