// navmesh_landmarks.hpp -- landmark lower bounds for the mesh search of navmesh.hpp (the
// ALT bounds of Goldberg and Harrelson, SODA 2005, on the free space's geodesic metric).
//
// A landmark is a mesh vertex L; its table holds d(v, L), the length of a shortest path
// from every search vertex v (mesh vertices, then the zero-width network's extra ones) to
// L, computed at preparation by a search from L over the whole mesh (MeshSearch's sweep
// mode: Polyanya without a target, every vertex seen in a cone or reached as a bend
// recording its length). By the triangle inequality of the geodesic metric,
//     d(v, t) >= d(v, L) - d(t, L)   and   d(v, t) >= d(t, L) - d(v, L),
// so with bounds lo <= d(t, L) <= hi for the query's target t (from the vertices of the
// convex cells holding t, which t sees: hi = min |t w| + d(w, L), lo = max d(w, L) - |t w|)
// the largest of d(v, L) - hi and lo - d(v, L) over the landmarks is a lower bound of the
// remaining length at v. The search keeps Polyanya's heuristic and takes the larger of
// the two (both are lower bounds, so the search stays optimal).
//
// Lengths are doubles: every table entry is a sum of at most (search vertices) rounded
// segment lengths, so its relative error is below eta = 4 (n + 16) 2^-53; the bounds are
// lowered by a slack that covers that error (and the rounding of the points where an
// interval meets its edge, a few units of 2^-53 of the scene's magnitude), so that a bound
// never exceeds the exact remaining length. An entry of +inf (L does not reach v) gives no
// bound; a landmark that does not reach the target is left out for that query.
//
// Landmarks are chosen farthest-first: the first is the vertex of the largest connected
// part of the mesh farthest from that part's centre, each next one the vertex whose
// least distance to the landmarks so far is largest. The tables cost a sweep each, and
// the bounds a little per node: they are made only where a few probe queries show
// shortest paths clearly longer than the straight line (MeshPlanner::min_detour), and
// kept only where they cut the probes' nodes by a tenth.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace mk {

struct MeshLandmarks {
  int K = 0;              // landmarks
  int n = 0;              // search vertex ids
  std::vector<int> at;    // each landmark's vertex id
  std::vector<double> d;  // d[v * K + l]: geodesic distance from vertex v to landmark l
  double eta = 0;         // relative error bound of an entry
  double dmax = 0;        // the largest finite entry

  bool empty() const { return K == 0; }
  const double* row(int v) const { return d.data() + (std::size_t)v * K; }

  // the next landmark: the vertex whose least distance to the ones so far is largest
  // (finite distances only: a vertex no landmark reaches is not chosen)
  int farthest(int nv) const {  // among the ids below nv (the mesh's vertices)
    int best = -1;
    double bd = -1;
    for (int v = 0; v < nv; ++v) {
      const double* r = row(v);
      double m = std::numeric_limits<double>::infinity();
      for (int l = 0; l < K; ++l) m = std::min(m, r[l]);
      if (m < std::numeric_limits<double>::infinity() && m > bd) {
        bd = m;
        best = v;
      }
    }
    return bd > 0 ? best : -1;
  }

  // append a landmark at vertex id v with its distances dist (n entries; +inf: unreached)
  void add(int v, const std::vector<double>& dist) {
    std::vector<double> nd((std::size_t)n * (K + 1));
    for (int u = 0; u < n; ++u) {
      std::copy(row(u), row(u) + K, nd.begin() + (std::size_t)u * (K + 1));
      nd[(std::size_t)u * (K + 1) + K] = dist[u];
      if (dist[u] < std::numeric_limits<double>::infinity()) dmax = std::max(dmax, dist[u]);
    }
    d = std::move(nd);
    at.push_back(v);
    ++K;
  }
};

// The bounds of one query: per landmark [lo, hi] around d(t, L), or unused.
struct LandmarkQuery {
  std::vector<double> lo, hi;
  std::vector<double> lb;       // per vertex id: its bound (< 0: not computed yet)
  std::vector<int> touched;     // vertex ids whose lb was set
  double slack = 0;             // subtracted from every bound (rounding, see above)
  bool on = false;

  // The target sees the vertices seen[k].first (straight, inside a convex cell or along
  // a zero-width segment) at lengths seen[k].second; scale: the scene's largest
  // coordinate. A landmark that does not reach all of them (the landmark and the target
  // are in different parts) is left out (lo = -inf, hi = +inf: it bounds nothing).
  void target(const MeshLandmarks& T, const std::vector<std::pair<int, double>>& seen,
              double scale) {
    on = false;
    if (T.empty() || seen.empty()) return;
    const double inf = std::numeric_limits<double>::infinity();
    lo.assign(T.K, -inf);
    hi.assign(T.K, inf);
    for (int l = 0; l < T.K; ++l) {
      double a = -inf, b = inf;
      for (const auto& [v, len] : seen) {
        const double x = T.row(v)[l];
        a = std::max(a, x - len);
        b = std::min(b, x + len);
      }
      if (!(a < inf)) continue;  // some vertex the target sees is not reached
      lo[l] = a;
      hi[l] = b;
      on = true;
    }
    if ((int)lb.size() != T.n) lb.assign(T.n, -1.0);
    // the entries' error (eta of each of two entries), the lengths |t w| and the
    // interval points' rounding (a few ulps of the scene's magnitude)
    slack = T.eta * (4 * T.dmax + 64 * scale);
  }

  // The bound at vertex id v (computed once per query). An entry +inf (the landmark does
  // not reach v, but reaches the target: no path joins them) gives +inf; with an unused
  // landmark (hi = +inf) it gives NaN, which std::max passes over.
  double at(const MeshLandmarks& T, int v) {
    if (lb[v] >= 0) return lb[v];
    const double* r = T.row(v);
    double b = 0;
    for (int l = 0; l < T.K; ++l) {
      b = std::max(b, r[l] - hi[l]);
      b = std::max(b, lo[l] - r[l]);
    }
    b = std::max(0.0, b - slack);
    touched.push_back(v);
    return lb[v] = b;
  }

  void clear() {
    for (int v : touched) lb[v] = -1.0;
    touched.clear();
    on = false;
  }
};

}  // namespace mk
