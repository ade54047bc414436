// Batched no-fit polygons with CGAL's minkowski_sum_2 (Epeck kernel), for bench_nfp.py,
// bench_nfp_free.py and the cross-check tests/test_cgal_crosscheck.py (tests/cgal_peer.py).
// Build: g++ -O2 -std=c++17 cgal_nfp_driver.cpp -o cgal_nfp_driver -lgmp -lmpfr
// Usage: cgal_nfp_driver METHOD FILE
//   METHOD: rc = reduced convolution (CGAL's default), hm = Hertel-Mehlhorn
//           decomposition; rc-exact / hm-exact: the same sums, printing every vertex.
// FILE: "N" then N polygons, each "n x0 y0 x1 y1 ..." (simple, either orientation), then
//       "M" and M lines "i j": the sum P_i (+) P_j (the caller passes the reflected part,
//       -B, as P_j). Each coordinate is read as a float64 (strtod: correctly rounded, so
//       Python's repr(float) comes back bit for bit) and enters the kernel as that exact
//       double, not as the decimal fraction it is written as.
// Output of rc / hm: one line per pair "area holes", then "seconds S" (the sums only:
//   reading and printing excluded).
// Output of rc-exact / hm-exact: per pair, in order,
//     nfp Q HOLES AREA            (AREA: the exact area, outer minus holes, as num/den)
//     outer N                     then N lines "xnum/xden ynum/yden", counter-clockwise
//     hole N                      (HOLES times) then N lines as above, clockwise
//   and a last line "seconds S". Every coordinate is CGAL::exact(.) of the vertex, printed
//   as numerator/denominator in lowest terms (the denominator is positive; "/1" included).
//   The rings are CGAL's as they come: a vertex may lie exactly on the segment between its
//   neighbours (the reader decides what to do with it).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/minkowski_sum_2.h>
#include <CGAL/Polygon_convex_decomposition_2.h>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_exact_constructions_kernel K;
typedef CGAL::Polygon_2<K> Polygon_2;
typedef CGAL::Polygon_with_holes_2<K> Pwh;
typedef K::FT FT;
typedef K::FT::ET ET;

static bool read_double(std::istream& in, double& v) {
  std::string tok;
  if (!(in >> tok)) return false;
  char* end = nullptr;
  v = std::strtod(tok.c_str(), &end);
  return end != tok.c_str() && *end == '\0';
}

static bool read_polygon(std::istream& in, Polygon_2& p) {
  long n = 0;
  if (!(in >> n) || n < 3) return false;
  for (long i = 0; i < n; ++i) {
    double x, y;
    if (!read_double(in, x) || !read_double(in, y)) return false;
    p.push_back(K::Point_2(x, y));
  }
  if (p.orientation() == CGAL::CLOCKWISE) p.reverse_orientation();
  return true;
}

static void print_exact(std::ostream& os, const FT& v) {
  typedef CGAL::Fraction_traits<ET> FTr;
  typename FTr::Numerator_type num;
  typename FTr::Denominator_type den;
  typename FTr::Decompose()(CGAL::exact(v), num, den);
  os << num << "/" << den;
}

static void print_ring(std::ostream& os, const char* tag, const Polygon_2& r) {
  os << tag << " " << r.size() << "\n";
  for (auto v = r.vertices_begin(); v != r.vertices_end(); ++v) {
    print_exact(os, v->x());
    os << " ";
    print_exact(os, v->y());
    os << "\n";
  }
}

int main(int argc, char** argv) {
  std::string m = argc == 3 ? argv[1] : "";
  bool exact_out = m == "rc-exact" || m == "hm-exact";
  bool hm_method = m == "hm" || m == "hm-exact";
  if (!(exact_out || m == "rc" || m == "hm")) {
    std::cerr << "usage: cgal_nfp_driver rc|hm|rc-exact|hm-exact FILE\n";
    return 2;
  }
  std::ifstream in(argv[2]);
  long n_poly = 0;
  in >> n_poly;
  std::vector<Polygon_2> polys(n_poly);
  for (long k = 0; k < n_poly; ++k) {
    if (!read_polygon(in, polys[k])) {
      std::cerr << "cgal_nfp_driver: polygon " << k << " is malformed\n";
      return 2;
    }
  }
  long n_pair = 0;
  in >> n_pair;
  std::vector<std::pair<long, long>> pairs(n_pair);
  for (auto& p : pairs) {
    if (!(in >> p.first >> p.second) || p.first < 0 || p.second < 0 || p.first >= n_poly ||
        p.second >= n_poly) {
      std::cerr << "cgal_nfp_driver: bad pair\n";
      return 2;
    }
  }
  std::vector<Pwh> out(n_pair);
  CGAL::Hertel_Mehlhorn_convex_decomposition_2<K> hm;
  auto t0 = std::chrono::steady_clock::now();
  for (long q = 0; q < n_pair; ++q) {
    const Polygon_2& P = polys[pairs[q].first];
    const Polygon_2& Q = polys[pairs[q].second];
    out[q] = hm_method ? CGAL::minkowski_sum_2(P, Q, hm) : CGAL::minkowski_sum_2(P, Q);
  }
  auto t1 = std::chrono::steady_clock::now();
  std::cout.precision(17);
  for (long q = 0; q < n_pair; ++q) {
    const Pwh& s = out[q];
    FT a = s.outer_boundary().area();
    for (auto h = s.holes_begin(); h != s.holes_end(); ++h) a += h->area();
    if (!exact_out) {
      std::cout << CGAL::to_double(a) << " " << s.number_of_holes() << "\n";
      continue;
    }
    std::cout << "nfp " << q << " " << s.number_of_holes() << " ";
    print_exact(std::cout, a);
    std::cout << "\n";
    print_ring(std::cout, "outer", s.outer_boundary());
    for (auto h = s.holes_begin(); h != s.holes_end(); ++h) print_ring(std::cout, "hole", *h);
  }
  std::cout << "seconds " << std::chrono::duration<double>(t1 - t0).count() << "\n";
  return 0;
}
