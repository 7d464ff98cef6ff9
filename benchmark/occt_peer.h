// OpenCASCADE as a benchmark-only peer (benchmark/install-peers.sh): a rational Bezier patch as a
// Geom_BezierSurface, and GeomAPI_IntSS's intersection curves of two of them, sampled as polylines. Compiled only
// when the benchmark's CMake found OpenCASCADE (BEZOUTIAN_WITH_OCCT).
#ifndef BEZOUTIAN_BENCHMARK_OCCT_PEER_H
#define BEZOUTIAN_BENCHMARK_OCCT_PEER_H

#ifdef BEZOUTIAN_WITH_OCCT
#include <bezoutian/geometry/Rational_bezier_patch.h>

#include <GeomAPI_IntSS.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_Curve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <algorithm>
#include <array>
#include <vector>

namespace occt_peer {

using Polyline = std::vector<std::array<double, 3>>;

inline Handle(Geom_BezierSurface) surface(const bezoutian::Rational_bezier_patch<>& p) {
  const int m = p.degree_u(), n = p.degree_v();
  TColgp_Array2OfPnt poles(1, m + 1, 1, n + 1);
  TColStd_Array2OfReal weights(1, m + 1, 1, n + 1);
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j) {
      const auto& h = p.homogeneous_control_point(std::size_t(i), std::size_t(j));
      const double wt = CGAL::to_double(h[0]);
      poles.SetValue(i + 1, j + 1, gp_Pnt(CGAL::to_double(h[1] / h[0]), CGAL::to_double(h[2] / h[0]),
                                          CGAL::to_double(h[3] / h[0])));
      weights.SetValue(i + 1, j + 1, wt);
    }
  return new Geom_BezierSurface(poles, weights);
}

/// GeomAPI_IntSS at tolerance 1e-7: whether it finished, its curves, each sampled at 401 points.
struct Result {
  bool done = false;
  int curves = 0;
  std::vector<Polyline> geometry;
};

inline Result intersect(const Handle(Geom_BezierSurface) & a, const Handle(Geom_BezierSurface) & b) {
  Result out;
  try {
    GeomAPI_IntSS inter(a, b, 1e-7);
    out.done = inter.IsDone();
    if (!out.done) return out;
    out.curves = inter.NbLines();
    for (int k = 1; k <= inter.NbLines(); ++k) {
      const Handle(Geom_Curve) c = inter.Line(k);
      const double t0 = std::max(c->FirstParameter(), -10.0), t1 = std::min(c->LastParameter(), 10.0);
      Polyline l;
      for (int i = 0; i <= 400; ++i) {
        const gp_Pnt p = c->Value(t0 + (t1 - t0) * i / 400);
        l.push_back({p.X(), p.Y(), p.Z()});
      }
      out.geometry.push_back(l);
    }
  } catch (const Standard_Failure&) {
    out.done = false;
  }
  return out;
}

}  // namespace occt_peer
#endif

#endif  // BEZOUTIAN_BENCHMARK_OCCT_PEER_H
