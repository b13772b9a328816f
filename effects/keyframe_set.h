/// @file
/// @brief One effect's editable keyframes with an always-available RBF solution.
///
/// Edits update the solution without a full O(N^3) solve where they can: a bordered (rank-one)
/// update of the explicit inverse of the saddle-point system, O(N^2) per add/remove/move, in
/// place in preallocated storage. The saddle matrix is cached, so the residual after each update
/// is one matrix product; a refinement step runs when it is above the full solve's threshold, and
/// the result is checked (fully, or at the new centre and a sample of others); a full re-solve
/// follows when it grew beyond tolerance, when the active polynomial terms change, or when
/// coincident keyframes need merging. Full re-solves of large sets run on a worker thread and are
/// swapped in when done: readers (the render thread) always get a complete solution via
/// solution(), possibly one edit behind, and version numbers say which.
///
/// Keyframes interpolated locally in time (a reach_s, or more than kGlobalSolveMaxKeyframes
/// keyframes: effects/rbf_windows.h) are kept in windows instead (effects/keyframe_windows.h):
/// an edit re-solves the few windows whose keyframes it changes, inline; the others are kept.
/// Only a change of the windows' layout (the automatic reach moves by a factor of two, or the
/// set crosses kGlobalSolveMaxKeyframes) solves every window again.
///
/// Threads: edits from one thread (the editor); solution(), solution_version() and
/// wait_for_version() from any thread.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "effects/keyframe.h"
#include "effects/keyframe_windows.h"
#include "effects/rbf_interpolator.h"

namespace vdfx::effects {

/// A keyframe added within this angle of an existing one at the same frame replaces it.
inline constexpr double kReplaceAngleDeg = 0.5;

/// The editing rule: a keyframe placed (or moved) at (direction, frame) replaces `other` when
/// both are at that frame and within kReplaceAngleDeg of each other.
bool replaces(const Direction& direction, std::int64_t frame, const Keyframe& other);

struct KeyframeSetOptions {
  bool async = true;  //!< false: full re-solves inline (batch tools, tests)
  //! Relative residual above which an update falls back to a full solve. Bordered updates of an
  //! explicit inverse carry ~cond * eps error (2e-9 at N = 1000 random keyframes, cond 3e7).
  double residual_tolerance = 1e-8;
  int inline_full_solve_max = 48;  //!< centres up to which a full solve is cheap enough inline
  //! false: an incremental update runs its refinement step only when the full residual (from
  //! the cached saddle matrix, O(N^2)) exceeds kRefineTolerance of the largest value, the full
  //! solve's own threshold. true: always (tests compare the two).
  bool always_refine = false;
};

/// Counters of the incremental path (editor thread), for tests and benchmarks.
struct KeyframeSetStats {
  std::uint64_t incremental_edits = 0;  //!< edits solved by an O(N^2) update
  std::uint64_t refinements = 0;        //!< of those, the ones that ran a refinement step
  std::uint64_t storage_growths = 0;    //!< reallocations of the incremental matrices by edits
  int capacity = 0;  //!< slots (terms + centres) the current matrices hold without reallocating
  //! Built by clone() from a copy of an exact incremental state (no solve ran).
  bool cloned_exact = false;
  std::uint64_t local_edits = 0;     //!< edits that re-solved only the windows they changed
  std::uint64_t windows_solved = 0;  //!< windows those edits solved
};

class KeyframeSet {
 public:
  struct Edit {
    std::size_t index = 0;                //!< where the keyframe now is
    std::optional<std::size_t> replaced;  //!< the keyframe it replaced (same index after add)
    //! Solved by an O(N^2) update, or (local interpolation) by re-solving only the windows the
    //! edit changed; else a full solve.
    bool incremental = false;
  };

  /// Solves the initial keyframes synchronously (load time). Throws std::invalid_argument like
  /// RbfInterpolator.
  KeyframeSet(int dimension, const InterpolationSettings& settings, double fps,
              std::vector<Keyframe> keyframes = {}, KeyframeSetOptions options = {},
              std::vector<double> neutral = {});
  ~KeyframeSet();
  KeyframeSet(const KeyframeSet&) = delete;

  /// A new, independent set with the same keyframes, settings, neutral values, version numbers
  /// and solution, with its own `options` (and its own worker when options.async). Interpolated
  /// locally, the clone shares the windows' solves (O(N) copying, no solve). When this set
  /// has its exact incremental state for its latest edit (also one a worker solved and has not
  /// handed over yet), the clone copies it: keyframes, centres, the saddle matrix and its inverse
  /// and the weights, O(N^2) memory traffic and no solve (stats().cloned_exact); the published
  /// interpolator, immutable, is shared. Otherwise (keyframes merged into one centre, an
  /// asynchronous re-solve still running, a set that fell back to a full solve and has no
  /// incremental state) it runs one full O(N^3) solve of the keyframes, synchronously. Either
  /// way the clone then edits exactly like a set solved from scratch. Editor thread only (the
  /// thread that edits this set).
  std::unique_ptr<KeyframeSet> clone(KeyframeSetOptions options) const;
  KeyframeSet& operator=(const KeyframeSet&) = delete;

  /// Adds a keyframe; one within kReplaceAngleDeg at the same frame is replaced in place.
  Edit add(Keyframe keyframe);
  /// Moves keyframe `index`; a keyframe it lands on (same rule as add) is removed.
  Edit move(std::size_t index, const Direction& direction, std::int64_t frame);
  void remove(std::size_t index);
  void set_params(std::size_t index, std::vector<double> params);
  /// Replaces every keyframe (undo, redo), solved synchronously like a new set of them with the
  /// same settings; interpolated locally, the windows whose keyframes did not change keep their
  /// solves. Throws std::invalid_argument like the constructor (the set is then unchanged).
  void assign(std::vector<Keyframe> keyframes);

  const std::vector<Keyframe>& keyframes() const { return keyframes_; }
  int dimension() const { return dimension_; }
  /// The keyframes are interpolated locally in time (their windows are kept).
  bool local() const { return local_ != nullptr; }
  /// Number of edits so far (0 after construction).
  std::uint64_t version() const { return version_; }
  /// Incremental-path counters (editor thread).
  KeyframeSetStats stats() const;

  /// The latest complete solution (any thread).
  std::shared_ptr<const RbfInterpolator> solution() const;
  std::uint64_t solution_version() const;
  /// Blocks until a solution of at least `version` is published; false on timeout.
  bool wait_for_version(std::uint64_t version, std::chrono::milliseconds timeout) const;

 private:
  struct State;   // incremental state: centres, basis, inverse, solution
  struct Worker;  // the asynchronous full solver
  struct CloneTag {};

  /// clone(): copies everything but the state, solves nothing, starts no worker.
  KeyframeSet(CloneTag, const KeyframeSet& source, KeyframeSetOptions options);
  void start_worker();

  static std::unique_ptr<State> solve_full(const std::vector<Keyframe>& keyframes, int dimension,
                                           const RbfKernel& kernel, const Eigen::VectorXd& neutral,
                                           std::uint64_t version);
  std::optional<std::size_t> find_coincident(const Direction& d, std::int64_t frame,
                                             std::optional<std::size_t> skip) const;
  void adopt_worker_result();
  bool try_add_centre(std::size_t keyframe_index);
  bool try_remove_centre(std::size_t keyframe_index);
  bool finish_incremental(int checked_centre);
  void flush_pending();
  void full_solve();
  /// Whether the keyframes as they are now are interpolated locally (plan_windows would say so).
  bool wants_local() const;
  /// After an edit of a locally interpolated set (or one that now wants to be): the windows it
  /// changed re-solved, or a full solve. Returns whether it stayed local and incremental.
  bool local_edit(const KeyframeChange& change);
  /// Makes `s` the published solution; a worker also hands over its exact state (adopted by
  /// the next edit on the caller's thread).
  void publish(std::shared_ptr<const RbfInterpolator> s, std::uint64_t version,
               std::unique_ptr<State> exact_state = nullptr) const;

  int dimension_;
  InterpolationSettings settings_;
  double fps_;
  RbfKernel kernel_;
  KeyframeSetOptions options_;
  Eigen::VectorXd neutral_;
  std::vector<Keyframe> keyframes_;
  std::uint64_t version_ = 0;
  std::unique_ptr<State> state_;            // null while no valid incremental state
  std::unique_ptr<KeyframeWindows> local_;  // non-null while interpolated locally
  KeyframeSetStats stats_;

  mutable std::mutex pub_mu_;
  mutable std::condition_variable pub_cv_;
  mutable std::shared_ptr<const RbfInterpolator> published_;
  mutable std::uint64_t published_version_ = 0;
  mutable std::unique_ptr<State> ready_;  // a worker result waiting to be adopted

  std::unique_ptr<Worker> worker_;
};

}  // namespace vdfx::effects
