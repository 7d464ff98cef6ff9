// The "locus" object of doc/json_schema.md: a surface locus (self-intersection or intersection of two patches) as
// `self-intersect`, `intersect` and `model` print it with --json.
//
// Every traced point is given by columns of one length: its projection (the point of D = 0: (u, v) for a
// self-intersection, (u, t) for two patches), its partner ((l, k) or (v, s)), both parameter points that map to
// the same point of space (first (u, v + k) and second (u + l, v) on the one patch; first (u, v) and second (s, t)
// on the two), the point of space, the genuine flag and whether that flag is proved. Traced points are floating-point
// approximations of points of the certified arcs; enclosures are proved and printed rounded outward.
#include "exact_json.h"
#include "implicit_json.h"
#include "locus_json.h"

#include <array>
#include <cstddef>
#include <string>

namespace bezoutian_cli {

std::string contact_kind(const bezoutian::Isolated_point_partners::Partner& p) {
  if (!p.tangency_decided) return "undecided";
  return p.singular ? "singular" : p.tangent ? "tangent" : "transversal";
}

namespace {

using nlohmann::json;

// The columns of a run of traced points.
struct Point_columns {
  json projection = json::array(), partner = json::array(), first = json::array(), second = json::array(),
       space = json::array(), genuine = json::array(), proved = json::array(), enclosures = json::array();

  void add(const bezoutian::Locus_point& q) {
    projection.push_back(approx(q.projection));
    partner.push_back(q.lifted ? approx(q.partner) : json(nullptr));
    first.push_back(q.lifted ? approx(q.first) : json(nullptr));
    second.push_back(q.lifted ? approx(q.second) : json(nullptr));
    space.push_back(q.lifted ? approx(q.point_3d) : json(nullptr));
    genuine.push_back(q.genuine);
    proved.push_back(q.status_proved);
    const auto& y = q.partner_enclosure;
    enclosures.push_back(std::isfinite(y[0][0]) ? json::array({enclosure(y[0][0], y[0][1]), enclosure(y[1][0], y[1][1])})
                                                : json(nullptr));
  }

  // The columns of the points into `j`.
  void write_points(json& j) const {
    j["projection_points"] = projection;
    j["partner_points"] = partner;
    j["first_points"] = first;
    j["second_points"] = second;
    j["points_3d"] = space;
  }
  // Also the genuine flags, whether each is proved, and the proved partner enclosures.
  void write_points_and_status(json& j) const {
    write_points(j);
    j["genuine"] = genuine;
    j["genuine_proved"] = proved;
    j["partner_enclosures"] = enclosures;
  }
};

json exact_box(const bezoutian::Parameter_box& b) { return {exact(b.u0), exact(b.u1), exact(b.v0), exact(b.v1)}; }

json vertex_json(const bezoutian::Curve_topology_vertex& v) {
  return {{"projection", approx(std::array<double, 2>{v.u, v.v})},
          {"box", json::array({enclosure(v.u_lo, v.u_hi), enclosure(v.v_lo, v.v_hi)})},
          {"branches", v.branches}};
}

json components_json(const bezoutian::Surface_locus& L) {
  const auto& T = L.topology;
  json comps = json::array();
  for (const auto& c : T.components) {
    Point_columns columns;
    json arcs = json::array();
    for (std::size_t ei : c.edges) {
      const auto& arc = L.arcs[ei];
      const std::size_t from = columns.projection.size();
      // every branch of the space curve over the arc: one sheet per partner (the genuine runs), with its points
      json sheets = json::array();
      for (const auto& sh : arc.sheets) {
        Point_columns sc;
        for (const auto& q : sh.points) sc.add(q);
        // per segment: proved bounds [first domain, second domain, space] on its distance from the curve, rounded
        // up (null: not proved)
        json bounds = json::array();
        for (const auto& b : sh.segment_distance_bounds)
          bounds.push_back(std::isfinite(b[0]) ? json{upper_bound(b[0]), upper_bound(b[1]), upper_bound(b[2])}
                                               : json(nullptr));
        json js{{"from", from + sh.first}, {"segment_distance_bounds", bounds}};
        sc.write_points(js);
        js["genuine_proved"] = sc.proved;
        sheets.push_back(js);
      }
      arcs.push_back({{"from", from},
                      {"count", arc.points.size()},
                      {"undecided_fraction", approx(arc.undecided_fraction)},
                      {"fibre_undecided_fraction", approx(arc.fibre_undecided_fraction)},
                      {"sheets", sheets}});
      for (const auto& q : arc.points) columns.add(q);
    }
    json jc{{"closed", c.closed}, {"isolated_point", c.isolated_point}, {"arcs", arcs}};
    columns.write_points_and_status(jc);
    // an isolated point of D = 0: its vertex, the only projection point, not traced (the other columns are empty)
    if (c.isolated_point && !c.vertices.empty()) {
      const auto& v = T.vertices[c.vertices[0]];
      jc["projection_points"].push_back(approx(std::array<double, 2>{v.u, v.v}));
    }
    comps.push_back(jc);
  }
  return comps;
}

json edge_lines_json(const bezoutian::Surface_locus& L) {
  static const char* causes[] = {"unexplained", "collapsed_edge", "shared_boundary_curve", "outside_partner_domain",
                                 "partner_iso_curve", "collapsed_point_off_partner", "curve_off_partner"};
  json edges = json::array();
  for (const auto& e : L.edge_lines) {
    Point_columns columns;
    for (const auto& q : e.points) columns.add(q);
    const std::string variable = e.side % 2 == 1 ? "u" : (L.self_intersection ? "v" : "t");
    json je{{"side", e.side},
            {"interior", e.interior},
            {"line", variable + " = " + exact(e.value)},
            {"value", exact(e.value)},
            {"cause", causes[int(e.cause)]},
            {"partner_side", e.partner_side},
            {"genuine", e.genuine},
            {"genuine_proved", e.status_proved},
            {"description", e.description}};
    columns.write_points(je);
    edges.push_back(je);
  }
  return edges;
}

json contacts_json(const bezoutian::Surface_locus& L) {
  json contacts = json::array();
  for (const auto& c : L.contacts)
    contacts.push_back({{"kind", c.shared_curve ? "shared_boundary" : "point"},
                        {"sides", {c.side_first, c.side_second}},
                        {"first", {algebraic(c.first_0), algebraic(c.first_1)}},
                        {"second", {algebraic(c.second_0), algebraic(c.second_1)}},
                        {"point_3d", approx(c.point)}});
  return contacts;
}

json overlaps_json(const bezoutian::Surface_locus& L) {
  json overlaps = json::array();
  for (const auto& ov : L.overlaps) {
    json first = json::array(), second = json::array();
    for (std::size_t k = 0; k < 4; ++k) {
      first.push_back(exact(ov.first[k]));
      second.push_back(exact(ov.second[k]));
    }
    overlaps.push_back({{"first", first},
                        {"second", second},
                        {"map", {{"u", ov.along_u.text(ov.swapped ? "t" : "s")},
                                 {"v", ov.along_v.text(ov.swapped ? "s" : "t")}}}});
  }
  return overlaps;
}

json isolated_points_json(const bezoutian::Surface_locus& L) {
  json isolated = json::array();
  for (const auto& ip : L.isolated_points) {
    const auto& x = ip.lift;
    json partners = json::array();
    for (const auto& p : x.partners)
      partners.push_back({{"partner", {algebraic(p.v), algebraic(p.s)}},
                          {"kind", contact_kind(p)},
                          {"point_3d", approx(p.point)}});
    json e{{"vertex", ip.vertex}, {"proved", x.proved}, {"genuine", ip.genuine()}, {"partners", partners},
           {"reason", x.reason}};
    if (x.exact) e["projection_exact"] = {exact(x.projection[0]), exact(x.projection[1])};
    isolated.push_back(e);
  }
  return isolated;
}

json split_points_json(const bezoutian::Surface_locus& L) {
  const auto& T = L.topology;
  json splits = json::array();
  for (const auto& sp : L.split_points) {
    std::size_t component = 0, offset = 0;
    for (std::size_t ci = 0; ci < T.components.size(); ++ci) {
      std::size_t off = 0;
      for (std::size_t ei : T.components[ci].edges) {
        if (ei == sp.arc) component = ci, offset = off;
        off += L.arcs[ei].points.size();
      }
    }
    const auto& q = L.arcs[sp.arc].points[sp.index];
    const char* names[2][2] = {{"u", "v"}, {L.self_intersection ? "u" : "s", L.self_intersection ? "v" : "t"}};
    splits.push_back({{"component", component},
                      {"point_index", offset + sp.index},
                      {"projection", approx(q.projection)},
                      {"box", json::array({enclosure(sp.box[0][0], sp.box[0][1]), enclosure(sp.box[1][0], sp.box[1][1])})},
                      {"partner_box", json::array({enclosure(sp.box[2][0], sp.box[2][1]), enclosure(sp.box[3][0], sp.box[3][1])})},
                      // the index in "contacts" when the split point is that exact contact of the boundary curves
                      {"contact", sp.contact >= 0 ? json(sp.contact) : json(nullptr)},
                      {"boundary", {{"point", sp.point == 0 ? "first" : "second"},
                                    {"parameter", names[sp.point][sp.coordinate]},
                                    {"value", exact(sp.bound)}}}});
  }
  return splits;
}

json pinch_points_json(const bezoutian::Surface_locus& L) {
  json pinch = json::array();
  for (const auto& p : L.pinch_points)
    pinch.push_back({{"projection", approx(std::array<double, 2>{p.u, p.v})},
                     {"box", json::array({exact_interval(p.box[0][0], p.box[0][1]), exact_interval(p.box[1][0], p.box[1][1])})},
                     {"kernel_direction", p.rank_zero ? "none (the Jacobian is zero)" : p.chart == 0 ? "(1, m)" : "(m, 1)"},
                     {"m", exact_interval(p.m[0], p.m[1])}});
  return pinch;
}

}  // namespace

nlohmann::json locus_json(const bezoutian::Surface_locus& L) {
  json j;
  j["self_intersection"] = L.self_intersection;
  j["variables"] = L.self_intersection
                       ? json{{"projection", {"u", "v"}}, {"partner", {"l", "k"}}, {"first", {"u", "v + k"}},
                              {"second", {"u + l", "v"}}}
                       : json{{"projection", {"u", "t"}}, {"partner", {"v", "s"}}, {"first", {"u", "v"}},
                              {"second", {"s", "t"}}};
  j["equation_computed"] = L.equation_computed;  // false: answered by a direct proof, without elimination
  j["implicit"] = implicit_json(L.equation);
  j["topology_computed"] = L.topology_computed;
  if (L.topology_computed) j["topology_method"] = L.topology_method.empty() ? "empty locus" : L.topology_method;
  if (!L.note.empty()) j["note"] = L.note;
  j["box"] = exact_box(L.topology.box);
  j["components"] = components_json(L);
  // sides of the box on D = 0 (collapsed edges, shared boundary curves): not part of the components above
  j["edge_lines"] = edge_lines_json(L);
  json singular = json::array(), boundary = json::array();
  for (const auto& v : L.topology.vertices) {
    json jv = vertex_json(v);
    // a contact with the domain edge from outside (or a domain corner that D = 0 passes from outside) is an
    // isolated point of the locus in the domain, but D = 0 is smooth there: a boundary point, not a singular one
    if ((v.kind == bezoutian::Curve_topology_vertex::singular || v.kind == bezoutian::Curve_topology_vertex::isolated) &&
        !v.on_boundary) {
      jv["isolated"] = v.kind == bezoutian::Curve_topology_vertex::isolated;
      singular.push_back(jv);
    }
    if (v.on_boundary) {
      jv["tangent_to_boundary"] = v.tangent_to_boundary;  // the curve touches the edge here (from inside: 2 arcs)
      jv["singular"] = v.singular_on_boundary;  // D = 0 is singular here (a corner: cusp or node; branches into the box)
      boundary.push_back(jv);
    }
  }
  j["singular_points"] = singular;
  j["boundary_points"] = boundary;
  // regions proved free of genuine points (no partner in the partner domain): D = 0 is not followed there
  json excluded = json::array();
  for (const auto& b : L.topology.excluded_regions) excluded.push_back(exact_box(b));
  j["excluded_regions"] = excluded;
  if (!L.self_intersection) {
    j["contacts"] = contacts_json(L);
    // common regions of the two domains (pieces of one surface), exact: {u0, u1, v0, v1} and {s0, s1, t0, t1}
    j["overlaps"] = overlaps_json(L);
    // isolated real points of D = 0: contacts of the patches (every real partner, exact) or phantoms
    j["isolated_points"] = isolated_points_json(L);
  }
  // where genuine parts of arcs end inside the box (the partner reaches the partner domain's boundary): a traced
  // point of its component (its projection_points[point_index]) and a box proved to hold exactly one such crossing
  j["split_points"] = split_points_json(L);
  if (L.self_intersection) {  // rank-1 points of the patch: where double curves end inside the domain
    j["pinch_points"] = pinch_points_json(L);
    j["pinch_points_complete"] = L.pinch_points_complete;
    if (!L.pinch_points_note.empty()) j["pinch_points_note"] = L.pinch_points_note;
  }
  j["lifting"] = "floating point along certified arcs (see doc/surface_intersection.md)";
  return j;
}

}  // namespace bezoutian_cli
