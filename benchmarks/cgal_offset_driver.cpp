// Times CGAL's offsets of a simple polygon by a disk (Minkowski_sum_2 package).
// Build: g++ -O2 -std=c++17 cgal_offset_driver.cpp -o cgal_offset_driver -lgmp -lmpfr
// Usage: cgal_offset_driver approx|exact FILE R [EPS] [REPEAT]
//   approx: approximated_offset_2(P, R, EPS) (Epick-style rational kernel, circle-segment
//           traits: arcs whose end points are rational, one-sided within EPS);
//   exact:  offset_polygon_2(P, R, conic traits) is not built here (needs CORE); the
//           "exact" mode uses approximated_offset_2 with EPS = 1e-12 * R instead.
//   FILE:   "N x0 y0 x1 y1 ..." (CGAL's .dat layout for one polygon).
// A negative R gives approximated_inset_2 (the erosion, as a list of polygons).
// Prints: seconds pieces components holes   (pieces = x-monotone curves of all
// boundaries; the best time of REPEAT runs, excluding reading the file).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gps_circle_segment_traits_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/approximated_offset_2.h>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <list>
#include <string>

typedef CGAL::Exact_predicates_exact_constructions_kernel K;
typedef CGAL::Polygon_2<K> Polygon_2;
typedef CGAL::Gps_circle_segment_traits_2<K> Traits;
typedef Traits::Polygon_2 Offset_polygon_2;
typedef Traits::Polygon_with_holes_2 Offset_pwh_2;

static Polygon_2 read_poly(const char* path) {
  std::ifstream in(path);
  Polygon_2 p;
  in >> p;
  if (p.orientation() == CGAL::CLOCKWISE) p.reverse_orientation();
  return p;
}

static std::size_t curves(const Offset_polygon_2& p) {
  return static_cast<std::size_t>(std::distance(p.curves_begin(), p.curves_end()));
}

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: cgal_offset_driver approx|exact FILE R [EPS] [REPEAT]\n";
    return 2;
  }
  std::string mode = argv[1];
  Polygon_2 P = read_poly(argv[2]);
  double r = std::stod(argv[3]);
  double eps = argc > 4 ? std::stod(argv[4]) : 1e-3 * r;
  int repeat = argc > 5 ? std::stoi(argv[5]) : 1;
  if (mode == "exact") eps = 1e-12 * r;
  double best = 1e300;
  std::size_t pieces = 0, comps = 0, holes = 0;
  for (int k = 0; k < repeat; ++k) {
    pieces = comps = holes = 0;
    auto t0 = std::chrono::steady_clock::now();
    if (r > 0) {
      Offset_pwh_2 res = CGAL::approximated_offset_2(P, K::FT(r), eps);
      auto t1 = std::chrono::steady_clock::now();
      best = std::min(best, std::chrono::duration<double>(t1 - t0).count());
      pieces = curves(res.outer_boundary());
      for (auto h = res.holes_begin(); h != res.holes_end(); ++h) pieces += curves(*h);
      comps = 1;
      holes = res.number_of_holes();
    } else {
      std::list<Offset_polygon_2> parts;
      CGAL::approximated_inset_2(P, K::FT(-r), eps, std::back_inserter(parts));
      auto t1 = std::chrono::steady_clock::now();
      best = std::min(best, std::chrono::duration<double>(t1 - t0).count());
      for (const auto& q : parts) pieces += curves(q);
      comps = parts.size();
    }
  }
  std::cout.precision(17);
  std::cout << best << " " << pieces << " " << comps << " " << holes << "\n";
  return 0;
}
