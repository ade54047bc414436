// nest.cpp -- the binding of nest.hpp into minkowski2d._core._ext: the Nester class,
// which keeps a problem and its best feasible layout between calls; every search call
// releases the GIL and runs `threads` independent searches from the same layout
// (deterministic: the lowest-numbered thread that succeeds wins).
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/tuple.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <utility>
#include <vector>

#include "bind.hpp"
#include "exact.hpp"
#include "nest.hpp"
#include "parallel.hpp"

namespace nb = nanobind;
using namespace nb::literals;
using mk::i64;

namespace mk_bind {
namespace {

template <class T>
std::vector<T> vec(const In1<T>& a) {
  return std::vector<T>(a.data(), a.data() + a.shape(0));
}

class Nester {
 public:
  Nester(In1<double> box, In1<double> ref, In2<double> xy, In1<i64> ring_off, In1<i64> nring,
         In1<double> nbox, In1<i64> ots, In1<i64> ots_off, In1<std::uint8_t> fixed,
         In1<double> width, In1<double> height, double margin, double grid,
         bool int_vertices) {
    P.int_vertices = int_vertices;
    P.n_ot = (int)ref.shape(0);
    P.box = vec(box);
    P.ref = vec(ref);
    P.xy.assign(xy.data(), xy.data() + 2 * xy.shape(0));
    P.ring_off = vec(ring_off);
    P.nring = vec(nring);
    P.nbox = vec(nbox);
    P.ots = vec(ots);
    P.ots_off = vec(ots_off);
    P.n_items = (int)ots_off.shape(0) - 1;
    P.fixed.assign(fixed.data(), fixed.data() + fixed.shape(0));
    P.width = vec(width);
    P.height = vec(height);
    P.n_bins = (int)width.shape(0);
    P.margin = margin;
    P.grid = grid;
    const std::size_t n = (std::size_t)P.n_items, k = (std::size_t)P.n_ot * P.n_ot;
    if (P.box.size() != 4 * (std::size_t)P.n_ot || P.nring.size() != k + 1 ||
        P.nbox.size() != 4 * k || P.fixed.size() != n || P.height.size() != P.width.size() ||
        P.ring_off.empty() || P.ring_off.back() != (i64)xy.shape(0) ||
        P.nring.back() + 1 != (i64)P.ring_off.size() || P.ots_off.back() != (i64)P.ots.size() ||
        !(grid > 0))
      throw nb::value_error("Nester: inconsistent problem arrays");
    for (i64 o : P.ots)
      if (o < 0 || o >= P.n_ot) throw nb::value_error("Nester: orientation out of range");
    mk::nest::build_slabs(P);
    best.bin.assign(n, 0);
    best.ot.assign(n, 0);
    best.x.assign(n, 0.0);
    best.y.assign(n, 0.0);
    best.length = P.width;
    best.bins_used = 1;
  }

  void set_params(int container_samples, int focus_samples, int vertex_samples,
                  int refine_top, int max_strikes, int max_no_improve, long long max_rounds,
                  double floor_rel, double min_step_rel) {
    prm.min_step_rel = min_step_rel;
    prm.container_samples = container_samples;
    prm.focus_samples = focus_samples;
    prm.vertex_samples = vertex_samples;
    prm.refine_top = std::max(1, refine_top);
    prm.max_strikes = max_strikes;
    prm.max_no_improve = max_no_improve;
    prm.max_rounds = max_rounds;
    prm.floor_rel = floor_rel;
  }

  void set_state(In1<i64> bin, In1<i64> ot, In1<double> x, In1<double> y, In1<double> length,
                 int bins_used) {
    const std::size_t n = (std::size_t)P.n_items;
    if ((std::size_t)bin.shape(0) != n || (std::size_t)ot.shape(0) != n ||
        (std::size_t)x.shape(0) != n || (std::size_t)y.shape(0) != n ||
        (int)length.shape(0) != P.n_bins || bins_used < 1 || bins_used > P.n_bins)
      throw nb::value_error("Nester.set_state: bad shapes");
    for (std::size_t i = 0; i < n; ++i) {
      if (bin.data()[i] < -1 || bin.data()[i] >= P.n_bins || ot.data()[i] < 0 ||
          ot.data()[i] >= P.n_ot)
        throw nb::value_error("Nester.set_state: bin or orientation out of range");
      best.bin[i] = (int)bin.data()[i];
      best.ot[i] = (int)ot.data()[i];
      best.x[i] = x.data()[i];
      best.y[i] = y.data()[i];
    }
    best.length = vec(length);
    best.bins_used = bins_used;
  }

  nb::tuple state() const {
    const std::size_t n = (std::size_t)P.n_items;
    std::vector<i64> b(n), o(n);
    for (std::size_t i = 0; i < n; ++i) {
      b[i] = best.bin[i];
      o[i] = best.ot[i];
    }
    return nb::make_tuple(to_numpy(b, n, 0), to_numpy(o, n, 0), to_numpy(best.x, n, 0),
                          to_numpy(best.y, n, 0), to_numpy(best.length, best.length.size(), 0),
                          best.bins_used);
  }

  // Overlap of the stored layout (0: feasible by the NFPs), and the colliding pairs.
  nb::tuple overlap() const {
    mk::nest::Search s(P, prm, 0);
    s.S = best;
    s.set_pad();
    s.recompute();
    std::vector<i64> pairs;
    for (int i = 0; i < P.n_items; ++i)
      for (int j = i + 1; j < P.n_items; ++j)
        if (s.ov[(std::size_t)i * P.n_items + j] > 0) {
          pairs.push_back(i);
          pairs.push_back(j);
        }
    return nb::make_tuple(s.total(), to_numpy(pairs, pairs.size() / 2, 2));
  }

  void clear_pool() { pool.clear(); }

  // Place the items of `order` (not placed yet: bin -1 in the stored layout) one by one
  // (Search::insert_lbf). Returns the index in `order` of the first item no bin had
  // room for, or -1 when all are placed; the stored layout keeps what was placed.
  i64 construct(In1<i64> order, std::uint64_t seed, int samples) {
    mk::nest::Search s(P, prm, seed);
    s.S = best;
    s.set_pad();
    const i64 n = (i64)order.shape(0);
    i64 failed = -1;
    {
      nb::gil_scoped_release nogil;
      for (i64 k = 0; k < n; ++k) {
        const i64 i = order.data()[k];
        if (i < 0 || i >= P.n_items || s.S.bin[(std::size_t)i] >= 0) continue;
        if (!s.insert_lbf((int)i, 0, samples)) {
          failed = k;
          break;
        }
        s.S.bins_used = std::max(s.S.bins_used, s.S.bin[(std::size_t)i] + 1);
      }
    }
    best = s.S;
    return failed;
  }

  // Overlap (unweighted) of item i placed at (b, ot, x, y) with the stored layout's items
  // of bin b (items of bin -1 are not placed yet): 0 when no NFP holds it strictly inside.
  double probe(int i, int b, int ot, double x, double y) const {
    if (i < 0 || i >= P.n_items || b < 0 || b >= P.n_bins || ot < 0 || ot >= P.n_ot)
      throw nb::value_error("Nester.probe: out of range");
    mk::nest::Search s(P, prm, 0);
    s.S = best;
    s.set_pad();
    return s.eval(i, b, ot, x, y, std::numeric_limits<double>::infinity());
  }

  // One attempt, `threads` searches from the stored layout:
  //   mode 0: shrink bin `bins_used - 1` to `length`, then separate;
  //   mode 1: close the last bin (its items go to the others), then separate;
  //   mode 2: separate the stored layout as it is;
  //   mode 3: take a layout of the pool of failed separations at the current lengths
  //           (better ones more often), disrupt it (swap two large items), separate.
  // A failed separation of modes 0 and 3 joins the pool (cleared on success).
  // On success the stored layout becomes the new one. Returns (success, moves).
  nb::tuple attempt(int mode, double length, std::uint64_t seed, int threads, double seconds) {
    if (mode == 1 && best.bins_used < 2) return nb::make_tuple(false, 0);
    const int nt = std::max(1, std::min(threads, 64));
    std::vector<std::unique_ptr<mk::nest::Search>> runs;
    for (int t = 0; t < nt; ++t)
      runs.emplace_back(new mk::nest::Search(P, prm, seed * 0x9E3779B97F4A7C15ULL + (std::uint64_t)t));
    std::vector<char> ok((std::size_t)nt, 0);
    {
      nb::gil_scoped_release nogil;
      const auto deadline =
          mk::nest::Clock::now() +
          std::chrono::duration_cast<mk::nest::Clock::duration>(
              std::chrono::duration<double>(seconds > 0 ? std::min(seconds, 1e6) : 1e6));
      auto work = [&](int t) {
        auto& s = *runs[(std::size_t)t];
        s.set_pad();
        if (mode == 3 && !pool.empty()) {
          double u = std::fabs(std::normal_distribution<double>(0.0, 0.25)(s.rng));
          std::size_t k = (std::size_t)(std::min(u, 0.999) * (double)pool.size());
          s.S = pool[k].first;
          s.disrupt();
        } else {
          s.S = best;
          if (mode == 0 || mode == 3) s.shrink_to(best.bins_used - 1, length);
          if (mode == 1) s.close_last();
        }
        ok[(std::size_t)t] = s.separate(deadline);
      };
      mk::parallel_threads(nt, work);
    }
    long long moves = 0;
    for (auto& r : runs) moves += r->moves;
    for (int t = 0; t < nt; ++t)
      if (ok[(std::size_t)t]) {
        best = runs[(std::size_t)t]->S;
        pool.clear();
        return nb::make_tuple(true, moves);
      }
    if (mode == 0 || mode == 3)
      for (int t = 0; t < nt; ++t) {
        auto& r = *runs[(std::size_t)t];
        double loss = r.total();
        auto it = std::lower_bound(pool.begin(), pool.end(), loss,
                                   [](const auto& e, double v) { return e.second < v; });
        pool.insert(it, {r.S, loss});
        if (pool.size() > 64) pool.pop_back();
      }
    // keep the least overlapping layout of a separation of the stored one (mode 2)
    if (mode == 2) {
      double b = -1;
      int arg = 0;
      for (int t = 0; t < nt; ++t) {
        double v = runs[(std::size_t)t]->total();
        if (b < 0 || v < b) b = v, arg = t;
      }
      best = runs[(std::size_t)arg]->S;
    }
    return nb::make_tuple(false, moves);
  }

 private:
  mk::nest::Problem P;
  mk::nest::Params prm;
  mk::nest::State best;
  std::vector<std::pair<mk::nest::State, double>> pool;
};

}  // namespace

void bind_nest(nb::module_& m) {
  nb::class_<Nester>(m, "Nester")
      .def(nb::init<In1<double>, In1<double>, In2<double>, In1<i64>, In1<i64>, In1<double>,
                    In1<i64>, In1<i64>, In1<std::uint8_t>, In1<double>, In1<double>, double,
                    double, bool>(),
           "box"_a.noconvert(), "ref"_a.noconvert(), "xy"_a.noconvert(),
           "ring_off"_a.noconvert(), "nring"_a.noconvert(), "nbox"_a.noconvert(),
           "ots"_a.noconvert(), "ots_off"_a.noconvert(), "fixed"_a.noconvert(),
           "width"_a.noconvert(), "height"_a.noconvert(), "margin"_a, "grid"_a, "int_vertices"_a)
      .def("set_params", &Nester::set_params)
      .def("set_state", &Nester::set_state, "bin"_a.noconvert(), "ot"_a.noconvert(),
           "x"_a.noconvert(), "y"_a.noconvert(), "length"_a.noconvert(), "bins_used"_a)
      .def("state", &Nester::state)
      .def("overlap", &Nester::overlap)
      .def("clear_pool", [](Nester& n) { n.clear_pool(); })
      .def("construct", &Nester::construct, "order"_a.noconvert(), "seed"_a, "samples"_a)
      .def("probe", &Nester::probe, "item"_a, "bin"_a, "ot"_a, "x"_a, "y"_a)
      .def("attempt", &Nester::attempt, "mode"_a, "length"_a, "seed"_a, "threads"_a,
           "seconds"_a);
}

}  // namespace mk_bind
