// Times CGAL's minkowski_sum_2 on two simple polygons (Epeck kernel).
// Build: g++ -O2 -std=c++17 cgal_driver.cpp -o cgal_driver -lgmp -lmpfr
// Usage: cgal_driver METHOD FILE_P FILE_Q   (METHOD: rc = reduced convolution,
//        hm = Hertel-Mehlhorn decomposition). Files: "N x0 y0 x1 y1 ..." integers.
// Prints: seconds area holes
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/minkowski_sum_2.h>
#include <CGAL/Polygon_convex_decomposition_2.h>
#include <CGAL/Small_side_angle_bisector_decomposition_2.h>
#include <chrono>
#include <fstream>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_exact_constructions_kernel K;
typedef CGAL::Polygon_2<K> Polygon_2;
typedef CGAL::Polygon_with_holes_2<K> Pwh;

static Polygon_2 read_poly(const char* path) {
  std::ifstream in(path);
  Polygon_2 p;
  in >> p;
  if (p.orientation() == CGAL::CLOCKWISE) p.reverse_orientation();
  return p;
}

static double pwh_area(const Pwh& s) {
  K::FT a = s.outer_boundary().area();
  for (auto h = s.holes_begin(); h != s.holes_end(); ++h) a += h->area();
  return CGAL::to_double(a);
}

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: cgal_driver rc|hm P Q\n";
    return 2;
  }
  std::string m = argv[1];
  Polygon_2 P = read_poly(argv[2]), Q = read_poly(argv[3]);
  auto t0 = std::chrono::steady_clock::now();
  Pwh s;
  if (m == "rc") {
    s = CGAL::minkowski_sum_2(P, Q);
  } else if (m == "hm") {
    CGAL::Hertel_Mehlhorn_convex_decomposition_2<K> hm;
    s = CGAL::minkowski_sum_2(P, Q, hm);
  } else if (m == "ssab") {
    CGAL::Small_side_angle_bisector_decomposition_2<K> ssab;
    s = CGAL::minkowski_sum_2(P, Q, ssab);
  } else {
    std::cerr << "unknown method " << m << "\n";
    return 2;
  }
  auto t1 = std::chrono::steady_clock::now();
  double sec = std::chrono::duration<double>(t1 - t0).count();
  std::cout.precision(17);
  std::cout << sec << " " << pwh_area(s) << " " << s.number_of_holes() << "\n";
  return 0;
}
