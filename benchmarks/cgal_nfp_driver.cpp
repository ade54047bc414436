// Batched no-fit polygons with CGAL's minkowski_sum_2 (Epeck kernel), for bench_nfp.py.
// Build: g++ -O2 -std=c++17 cgal_nfp_driver.cpp -o cgal_nfp_driver -lgmp -lmpfr
// Usage: cgal_nfp_driver METHOD FILE   (METHOD: rc = reduced convolution, CGAL's default;
//        hm = Hertel-Mehlhorn decomposition).
// FILE: "N" then N polygons, each "n x0 y0 x1 y1 ..." (integers), then "M" and M lines
//       "i j": the sum P_i (+) P_j (the caller passes the reflected part, -B, as P_j).
// Prints one line per pair "area holes" and a last line "seconds S" (the sums only,
// reading and printing excluded).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/minkowski_sum_2.h>
#include <CGAL/Polygon_convex_decomposition_2.h>
#include <chrono>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_exact_constructions_kernel K;
typedef CGAL::Polygon_2<K> Polygon_2;
typedef CGAL::Polygon_with_holes_2<K> Pwh;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: cgal_nfp_driver rc|hm FILE\n";
    return 2;
  }
  std::string m = argv[1];
  std::ifstream in(argv[2]);
  long n_poly = 0;
  in >> n_poly;
  std::vector<Polygon_2> polys(n_poly);
  for (long k = 0; k < n_poly; ++k) {
    in >> polys[k];
    if (polys[k].orientation() == CGAL::CLOCKWISE) polys[k].reverse_orientation();
  }
  long n_pair = 0;
  in >> n_pair;
  std::vector<std::pair<long, long>> pairs(n_pair);
  for (auto& p : pairs) in >> p.first >> p.second;
  std::vector<Pwh> out(n_pair);
  CGAL::Hertel_Mehlhorn_convex_decomposition_2<K> hm;
  auto t0 = std::chrono::steady_clock::now();
  for (long q = 0; q < n_pair; ++q) {
    const Polygon_2& P = polys[pairs[q].first];
    const Polygon_2& Q = polys[pairs[q].second];
    out[q] = m == "hm" ? CGAL::minkowski_sum_2(P, Q, hm) : CGAL::minkowski_sum_2(P, Q);
  }
  auto t1 = std::chrono::steady_clock::now();
  std::cout.precision(17);
  for (const Pwh& s : out) {
    K::FT a = s.outer_boundary().area();
    for (auto h = s.holes_begin(); h != s.holes_end(); ++h) a += h->area();
    std::cout << CGAL::to_double(a) << " " << s.number_of_holes() << "\n";
  }
  std::cout << "seconds " << std::chrono::duration<double>(t1 - t0).count() << "\n";
  return 0;
}
