// Exact file formats (JSON, CGAL .dat, BPT), numbers and polynomial expressions.
// Reference values come from outside the readers: the dhermes/bezier fixtures (implicit equations),
// the teapot data (indexed copy and topology file), C's strtod for hex floats, the seed's polynomials
// typed in as C++ arithmetic, and algebraic identities (circle equations, subdivision by blossoming).
#include <bezoutian/io/Geometry_document.h>
#include <bezoutian/io/Json_format.h>
#include <bezoutian/io/Polynomial_expression.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "test_support.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using namespace bezoutian;
using namespace bezoutian::io;
using bezoutian_test::shared_data;
using bezoutian_test::source_file;

namespace {

using Curve_2 = Geometry_document::Curve_2;
using Curve_3 = Geometry_document::Curve_3;
using Patch = Geometry_document::Patch;
using P1 = Polynomial_1<Rational>;
using P2 = Polynomial_2<Rational>;

Rational q(const char* s) { return Rational(std::string(s)); }  // CGAL's own "p/q" reader, independent of ours

// A value of a dhermes fixture: an int or a string "p/q" / hex float.
Rational dhermes_number(const nlohmann::json& v) {
  if (v.is_number_integer()) return Rational(v.get<long long>());
  return exact_number(v.get<std::string>());
}

struct Marked {
  std::string text;
  std::size_t line, column;
};
// The expected error position is marked by '@' in the test input (independent of the reader's bookkeeping).
Marked unmark(const std::string& marked) {
  const std::size_t at = marked.find('@');
  REQUIRE(at != std::string::npos);
  Marked m{marked.substr(0, at) + marked.substr(at + 1), 1, 1};
  for (std::size_t i = 0; i < at; ++i) {
    if (marked[i] == '\n') {
      ++m.line;
      m.column = 1;
    } else {
      ++m.column;
    }
  }
  return m;
}

template <class Reader>
void check_parse_error(Reader read, const std::string& file, const std::string& marked, const std::string& message) {
  const Marked m = unmark(marked);
  INFO("input: " << marked);
  try {
    read(m.text, file);
    FAIL("no Parse_error");
  } catch (const Parse_error& e) {
    INFO("error: " << e.what());
    CHECK(e.file() == file);
    CHECK(e.line() == m.line);
    CHECK(e.column() == m.column);
    CHECK(std::string(e.what()).find(message) != std::string::npos);
    CHECK(std::string(e.what()).rfind(file + ":" + std::to_string(m.line) + ":" + std::to_string(m.column) + ": ", 0) == 0);
  }
}

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("bezoutian_io_test_" + name)).string();
}

} // namespace

// ------------------------------------------------------------------------------------------ numbers

TEST_CASE("exact numbers: integers, fractions, decimals and hex floats", "[formats][numbers]") {
  const std::vector<std::pair<std::string, Rational>> table = {
      {"0", Rational(0)},
      {"-12", Rational(-12)},
      {"+7", Rational(7)},
      {"3/4", Rational(3, 4)},
      {"-6/8", Rational(-3, 4)},
      {"0.784", Rational(98, 125)},
      {"2.53125", Rational(81, 32)},
      {"-2.5e-3", Rational(-1, 400)},
      {"1E3", Rational(1000)},
      {".5", Rational(1, 2)},
      {"5.", Rational(5)},
      {"1.5/2", Rational(3, 4)},
      {"  42  ", Rational(42)},
      {"0x1.8p1", Rational(3)},
      {"0x10", Rational(16)},
      {"-0x1p-3", Rational(-1, 8)},
      {"0X1.Ap0", Rational(13, 8)},
      {"123456789012345678901234567890", q("123456789012345678901234567890")},
  };
  for (const auto& row : table) {
    INFO(row.first);
    Exact_number_result r = parse_exact_number(row.first);
    REQUIRE(r.ok);
    CHECK(r.value == row.second);
  }
  // hex floats are exactly the doubles C's strtod reads
  for (const char* h : {"0x1.b7537f52e7c79p-3", "-0x1.5555555555555p-2", "0x1.fffffffffffffp+1023", "0x1p-1074"}) {
    INFO(h);
    CHECK(exact_number(h) == Rational(std::strtod(h, nullptr)));
  }
  // bad numbers: offset of the offending character
  const std::vector<std::pair<std::string, std::size_t>> bad = {
      {"", 0}, {"abc", 0}, {"1/0", 2}, {"3/-4", 2}, {"1e", 2}, {"1.2.3", 3}, {"0x", 2}, {"inf", 0}, {"-nan", 1},
      {"1e999999999", 2}, {"2 3", 2}, {"1/", 2}};
  for (const auto& b : bad) {
    INFO("'" << b.first << "'");
    Exact_number_result r = parse_exact_number(b.first);
    CHECK_FALSE(r.ok);
    CHECK(r.error_offset == b.second);
    CHECK_THROWS_AS(exact_number(b.first), Invalid_input);
  }
}

TEST_CASE("exact numbers: a 1,200-digit numerator parses exactly, a 10,000-digit one is refused", "[formats][numbers]") {
  // 1,200 digits: about 3,986 bits, under max_number_bits = 4096
  std::string digits;
  for (int i = 0; i < 1200; ++i) digits += char('1' + (i * 7 + 3) % 9);
  const Integer n(digits);  // GMP's own reader
  const Rational r = exact_number(digits + "/7");
  CHECK(r * Rational(7) == Rational(n));
  // inside JSON: as a string and as a bare JSON integer literal
  const std::string json = "{\"curve\": {\"points\": [[\"" + digits + "/7\", 0], [" + digits + ", 1]]}}";
  Geometry_document d = read_json(json);
  REQUIRE(d.curves_2.size() == 1);
  CHECK(d.curves_2[0].control_point(0)[0] == r);
  CHECK(d.curves_2[0].control_point(1)[0] == Rational(n));
  // 10,000 digits (33,216 bits or so): refused, saying why
  std::string many;
  for (int i = 0; i < 10000; ++i) many += char('1' + (i * 7 + 3) % 9);
  const Exact_number_result big = parse_exact_number(many);
  CHECK_FALSE(big.ok);
  CHECK(big.error_offset == 0);
  CHECK(big.message.find("number too large") != std::string::npos);
  CHECK_THROWS_WITH(read_json("{\"curve\": {\"points\": [[0, 0], [" + many + ", 1]]}}"),
                    Catch::Contains("number too large"));
}

TEST_CASE("exact numbers: printing round-trips", "[formats][numbers]") {
  for (const char* s : {"0", "-3", "98/125", "-1/3", "81/32", "123456789012345678901234567891/7"}) {
    const Rational x = q(s);
    CHECK(to_exact_string(x) == s);
    CHECK(exact_number(to_exact_decimal_string(x)) == x);
  }
  CHECK(to_exact_decimal_string(q("98/125")) == "0.784");
  CHECK(to_exact_decimal_string(q("-81/32")) == "-2.53125");
  CHECK(to_exact_decimal_string(q("1/400")) == "0.0025");
  CHECK(to_exact_decimal_string(q("1/3")) == "1/3");
  CHECK(to_exact_decimal_string(q("120")) == "120");
}

// -------------------------------------------------------------------------------------- expressions

TEST_CASE("polynomial expressions: the seed's surface, implicit and explicit products", "[formats][expressions]") {
  // buse-elkadi-galligo-2008 section 4, as printed (juxtaposition) and with explicit '*'
  const P2 phi1 = parse_polynomial_2("2s^2 - t^2 s^2 - 5 t s^2 + 7 s + 3 t^2 s + s t - 1 + 6 t^2 - 2 t", "s", "t");
  const P2 phi1_explicit =
      parse_polynomial_2("2*s^2 - t^2*s^2 - 5*t*s^2 + 7*s + 3*t^2*s + s*t - 1 + 6*t^2 - 2*t", "s", "t");
  CHECK(phi1 == phi1_explicit);
  // against the polynomial typed in as C++ arithmetic, at several rational points
  for (const auto& st : std::vector<std::pair<Rational, Rational>>{{q("1/3"), q("-2/7")}, {q("5"), q("3/2")}, {q("-1"), q("0")}}) {
    const Rational s = st.first, t = st.second;
    const Rational expected = 2 * s * s - t * t * s * s - 5 * t * s * s + 7 * s + 3 * t * t * s + s * t - 1 + 6 * t * t - 2 * t;
    const Rational value = phi1.evaluate(P1(t)).evaluate(s);  // outer t, inner s
    CHECK(value == expected);
  }
  CHECK(parse_polynomial_1("(t+1)^3", "t") == P1(Rational(1), Rational(3), Rational(3), Rational(1)));
  CHECK(parse_polynomial_1("(t+1)(t-1)", "t") == P1(Rational(-1), Rational(0), Rational(1)));
  CHECK(parse_polynomial_1("3/4*t - t/2 + 0.25 + 0x1p-2", "t") == P1(Rational(1, 2), Rational(1, 4)));
  CHECK(parse_polynomial_1("-t^2", "t") == P1(Rational(0), Rational(0), Rational(-1)));
  CHECK(parse_polynomial_1("t**2 - 2e1", "t") == P1(Rational(-20), Rational(0), Rational(1)));
  CHECK(parse_polynomial_1("2^10", "t") == P1(Rational(1024)));
  CHECK(parse_polynomial_1("t - t", "t") == P1(Rational(0)));
  // printing reads back
  const P2 back = parse_polynomial_2(polynomial_to_string(phi1, "u", "v"), "u", "v");
  CHECK(back == phi1);
  const P1 p = parse_polynomial_1("-3/4*t^3 + t - 7", "t");
  CHECK(parse_polynomial_1(polynomial_to_string(p, "x"), "x") == p);
}

TEST_CASE("polynomial expressions: errors give the offending offset", "[formats][expressions]") {
  const std::vector<std::pair<std::string, std::size_t>> bad = {
      {"2*s^", 4}, {"s^-1", 2}, {"s + q*t", 4}, {"(s + t", 6}, {"s/t", 2}, {"s/0", 2},
      {"", 0}, {"s +", 3}, {"s ^ 1.5", 4}, {"st", 0}, {"s^200", 1}, {"2 3", 2}, {"s^99999999999", 2}};
  for (const auto& b : bad) {
    INFO("'" << b.first << "'");
    try {
      parse_polynomial_2(b.first, "s", "t");
      FAIL("no error");
    } catch (const Expression_error& e) {
      INFO(e.what());
      CHECK(e.offset() == b.second);
    }
  }
  // nesting and sizes are bounded (no hang, no stack overflow)
  CHECK_THROWS_AS(parse_polynomial_1(std::string(100000, '(') + "t", "t"), Expression_error);
  CHECK_THROWS_AS(parse_polynomial_1(std::string(100000, '-') + "t", "t"), Expression_error);
  CHECK_THROWS_AS(parse_polynomial_1("(1e100000)^10000", "t"), Expression_error);
  CHECK_THROWS_AS(parse_polynomial_1("((t+1)^50)^50", "t"), Expression_error);
  // coefficients grown by expansion are bounded like numbers read: (10^1000)^2 t has 6,644 bits, 10^1000 t 3,322
  CHECK_THROWS_WITH(parse_polynomial_1("(1e1000)^2*t", "t"), Catch::Contains("has 6644 bits (at most 4096)"));
  CHECK_THROWS_WITH(parse_polynomial_1("1e1000*1e1000*t + 1", "t"), Catch::Contains("bits (at most 4096)"));
  CHECK(parse_polynomial_1("1e1000*t", "t") == Polynomial_1<Rational>(Rational(0), exact_number("1e1000")));
}

// --------------------------------------------------------------------------------- dhermes fixtures

TEST_CASE("dhermes/bezier curves: 77 curves read exactly, 66 lie on their implicit equation", "[formats][dhermes]") {
  std::ifstream in(shared_data("dhermes_bezier/tests/functional/curves.json"));
  REQUIRE(in);
  const nlohmann::json all = nlohmann::json::parse(in);
  std::size_t curves = 0, implicit = 0, hex = 0;
  std::map<int, int> degrees;
  Geometry_document doc;
  for (auto it = all.begin(); it != all.end(); ++it) {
    const nlohmann::json& cp = it.value().at("control_points");  // two rows: x row, y row
    REQUIRE(cp.size() == 2);
    std::vector<Curve_2::Point> points;
    for (std::size_t i = 0; i < cp[0].size(); ++i) {
      for (int k = 0; k < 2; ++k)
        if (cp[k][i].is_string() && cp[k][i].get<std::string>().find("0x") != std::string::npos) {
          ++hex;  // an exact dyadic: equal to what strtod reads
          const std::string h = cp[k][i].get<std::string>();
          CHECK(exact_number(h) == Rational(std::strtod(h.c_str(), nullptr)));
        }
      points.push_back({dhermes_number(cp[0][i]), dhermes_number(cp[1][i])});
    }
    const Curve_2 c(points);
    doc.add(c, "dhermes " + it.key());
    ++curves;
    ++degrees[c.degree()];
    if (!it.value().contains("implicitized")) continue;
    ++implicit;
    // f(x,y) = sum coef x^a y^b; homogenize with W and substitute the exact power form: identically 0
    const Curve_2::Power_form p = c.power_form();
    int total = 0;
    for (const auto& term : it.value().at("implicitized")) total = std::max(total, term[1].get<int>() + term[2].get<int>());
    P1 f(Rational(0));
    for (const auto& term : it.value().at("implicitized")) {
      const int a = term[1].get<int>(), b = term[2].get<int>();
      f += P1(dhermes_number(term[0])) * CGAL::ipower(p[1], a) * CGAL::ipower(p[2], b) * CGAL::ipower(p[0], total - a - b);
    }
    INFO("curve " << it.key());
    CHECK(CGAL::is_zero(f));
  }
  CHECK(curves == 77);
  CHECK(implicit == 66);
  CHECK(hex > 0);
  CHECK(degrees == std::map<int, int>{{1, 21}, {2, 44}, {3, 11}, {4, 1}});  // README counts

  // the same curves through our JSON (Bernstein and power) and .dat files
  const Geometry_document j = read_json(write_json(doc));
  const Geometry_document jp = read_json(write_json(doc, {Json_basis::power}));
  const Geometry_document d = read_dat(write_dat(doc));
  REQUIRE(j.curves_2.size() == 77);
  REQUIRE(jp.curves_2.size() == 77);
  REQUIRE(d.curves_2.size() == 77);
  for (std::size_t i = 0; i < 77; ++i) {
    CHECK(j.curves_2[i] == doc.curves_2[i]);
    CHECK(j.curve_2_name(i) == doc.curve_2_name(i));
    CHECK(jp.curves_2[i] == doc.curves_2[i]);
    CHECK(d.curves_2[i] == doc.curves_2[i]);
  }
}

// ------------------------------------------------------------------------------------------ teapot

namespace {
// side of Rational_bezier_patch::boundary_curve for "row0", "row3", "col0", "col3" of a bicubic net
int side_of(const std::string& what) {
  if (what == "row0") return 3;  // u = 0
  if (what == "row3") return 1;  // u = 1
  if (what == "col0") return 0;  // v = 0
  if (what == "col3") return 2;  // v = 1
  FAIL("unknown boundary " << what);
  return -1;
}
} // namespace

TEST_CASE("teapot: 32 bicubic patches, exact, matching the indexed copy", "[formats][teapot]") {
  const Geometry_document d = read_geometry_file(shared_data("teapot/teapot32.bpt"));
  REQUIRE(d.patches.size() == 32);
  for (const Patch& p : d.patches) CHECK(p.bidegree() == std::make_pair(3, 3));
  CHECK(d.patches[0].control_point(0, 1) == Patch::Point{q("7/5"), q("-98/125"), q("12/5")});  // "1.4 -0.784 2.4"

  // teapot32_indexed.txt: "V 290", "i x y z" lines, "P 32", "name i00 .. i33" (row-major)
  std::ifstream in(shared_data("teapot/teapot32_indexed.txt"));
  REQUIRE(in);
  std::string line;
  std::vector<Patch::Point> vertices;
  std::size_t patch = 0;
  bool in_patches = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::string first;
    ls >> first;
    if (first == "V") continue;
    if (first == "P") {
      in_patches = true;
      continue;
    }
    if (!in_patches) {
      std::string x, y, z;
      ls >> x >> y >> z;
      vertices.push_back({exact_number(x), exact_number(y), exact_number(z)});
      continue;
    }
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) {
        std::size_t index;
        ls >> index;
        REQUIRE(index < vertices.size());
        CHECK(d.patches[patch].control_point(r, c) == vertices[index]);
      }
    ++patch;
  }
  CHECK(vertices.size() == 290);
  CHECK(patch == 32);

  // the .bpt writer reproduces the file byte for byte (decimals written as decimals)
  CHECK(write_bpt(d) == read_text_file(shared_data("teapot/teapot32.bpt")));
}

TEST_CASE("teapot: the 52 shared boundaries of the topology file coincide exactly", "[formats][teapot]") {
  const Geometry_document d = read_geometry_file(shared_data("teapot/teapot32.bpt"));
  std::ifstream in(shared_data("teapot/teapot32_topology.txt"));
  REQUIRE(in);
  // "   0(rim).col3 (v=1) ==  1(rim).col0 (v=0)" or "... == reversed 31(bottom).row3 (u=1)"
  const std::regex shared(R"(^\s*(\d+)\(\w+\)\.(row\d|col\d).*==\s*(reversed\s+)?(\d+)\(\w+\)\.(row\d|col\d))");
  std::string line;
  std::size_t pairs = 0;
  while (std::getline(in, line)) {
    std::smatch m;
    if (!std::regex_search(line, m, shared)) continue;
    const int a = std::stoi(m[1]), b = std::stoi(m[4]);
    const Curve_3 ca = d.patches[a].boundary_curve<Curve_3>(side_of(m[2]));
    Curve_3 cb = d.patches[b].boundary_curve<Curve_3>(side_of(m[5]));
    if (m[3].matched) cb = cb.reversed();
    INFO(line);
    CHECK(ca == cb);
    ++pairs;
  }
  CHECK(pairs == 52);
}

TEST_CASE("sample: teapot body and handle in JSON equal the BPT patches", "[formats][samples]") {
  const Geometry_document bpt = read_geometry_file(shared_data("teapot/teapot32.bpt"));
  const Geometry_document j = read_geometry_file(source_file("examples/data/teapot_body_handle.json"));
  REQUIRE(j.patches.size() == 12);
  for (std::size_t i = 0; i < 12; ++i) {
    CHECK(j.patches[i] == bpt.patches[4 + i]);
    CHECK(j.patch_name(i).find("patch " + std::to_string(4 + i)) != std::string::npos);
  }
}

// -------------------------------------------------------------------------------- shipped samples

TEST_CASE("sample: the seed's worked example surface", "[formats][samples]") {
  const Geometry_document d = read_geometry_file(source_file("examples/data/bezoutian_worked_example.json"));
  REQUIRE(d.patches.size() == 1);
  const Patch& p = d.patches[0];
  CHECK(p.bidegree() == std::make_pair(2, 2));
  CHECK_FALSE(p.is_rational());
  // Phi(s,t) of buse-elkadi-galligo-2008 section 4, typed in as C++ arithmetic
  for (const auto& st : std::vector<std::pair<Rational, Rational>>{
           {q("0"), q("0")}, {q("1"), q("1")}, {q("1/3"), q("3/4")}, {q("-21/20"), q("-49/1000")}, {q("2"), q("-5")}}) {
    const Rational s = st.first, t = st.second;
    const Patch::Point expected{
        2 * s * s - t * t * s * s - 5 * t * s * s + 7 * s + 3 * t * t * s + s * t - 1 + 6 * t * t - 2 * t,
        9 * t * t * s * s - 5 * t * s * s + 2 * t * t * s + 4 * s * t + s - 7 * t * t + 9 * t,
        t * s * s + 2 * s * t - 2 * t * t};
    CHECK(p(s, t) == expected);
  }
}

TEST_CASE("sample: two rational circle arcs", "[formats][samples]") {
  const Geometry_document d = read_geometry_file(source_file("examples/data/circle_arcs.json"));
  REQUIRE(d.curves_2.size() == 4);
  // Bernstein and power versions are the same parametrizations
  CHECK(d.curves_2[0] == d.curves_2[2]);
  CHECK(d.curves_2[1] == d.curves_2[3]);
  // on the circles: X^2 + Y^2 = W^2 and (X - 6/5 W)^2 + Y^2 = W^2, identically
  const auto a = d.curves_2[0].power_form(), b = d.curves_2[1].power_form();
  CHECK(CGAL::is_zero(a[1] * a[1] + a[2] * a[2] - a[0] * a[0]));
  const P1 bx = b[1] - P1(Rational(6, 5)) * b[0];
  CHECK(CGAL::is_zero(bx * bx + b[2] * b[2] - b[0] * b[0]));
  // they cross at (3/5, 4/5), at t = 1/2 on both
  CHECK(d.curves_2[0](Rational(1, 2)) == Curve_2::Point{q("3/5"), q("4/5")});
  CHECK(d.curves_2[1](Rational(1, 2)) == Curve_2::Point{q("3/5"), q("4/5")});
}

// ------------------------------------------------------------------------------------- round trips

namespace {
Geometry_document mixed_document() {
  Geometry_document doc;
  doc.add(Curve_2({{q("1"), q("0")}, {q("1"), q("1")}, {q("0"), q("1")}}, {q("1"), q("-1/3"), q("2")}), "rational, \"quoted\"");
  doc.add(Curve_2::from_homogeneous({{q("1"), q("0"), q("0")}, {q("0"), q("1"), q("-1")}, {q("2"), q("2"), q("4")}}),
          "point at infinity");
  doc.add(Curve_3({{q("1/3"), q("0"), q("-5")}, {q("2"), q("7/9"), q("1")}}), "");
  doc.add(Curve_3::from_homogeneous({{q("1"), q("0"), q("0"), q("0")}, {q("0"), q("0"), q("0"), q("1")}}), "3d at infinity");
  std::vector<std::vector<Patch::Point>> net;
  std::vector<std::vector<Rational>> w;
  for (int i = 0; i <= 2; ++i) {
    net.emplace_back();
    w.emplace_back();
    for (int j = 0; j <= 3; ++j) {
      net.back().push_back({Rational(i * j, 3), Rational(i - j, 7), Rational(i * i + j, 5)});
      w.back().push_back(Rational(1 + i + j * j, 2 + i));
    }
  }
  doc.add(Patch(net, w), "rational (2,3) patch");
  doc.add(Patch(net), "");
  Patch::Net h = Patch(net, w).homogeneous_net();
  h[1][2][0] = Rational(0);
  doc.add(Patch::from_homogeneous(h), "patch with a point at infinity");
  doc.add(Patch(std::vector<std::vector<Patch::Point>>{{{q("1"), q("2"), q("3")}}}), "degree (0,0)");
  return doc;
}

void check_same(const Geometry_document& a, const Geometry_document& b) {
  REQUIRE(a.curves_2.size() == b.curves_2.size());
  REQUIRE(a.curves_3.size() == b.curves_3.size());
  REQUIRE(a.patches.size() == b.patches.size());
  for (std::size_t i = 0; i < a.curves_2.size(); ++i) {
    CHECK(a.curves_2[i] == b.curves_2[i]);
    CHECK(a.curve_2_name(i) == b.curve_2_name(i));
  }
  for (std::size_t i = 0; i < a.curves_3.size(); ++i) {
    CHECK(a.curves_3[i] == b.curves_3[i]);
    CHECK(a.curve_3_name(i) == b.curve_3_name(i));
  }
  for (std::size_t i = 0; i < a.patches.size(); ++i) {
    CHECK(a.patches[i] == b.patches[i]);
    CHECK(a.patch_name(i) == b.patch_name(i));
  }
}
} // namespace

TEST_CASE("round trips: JSON Bernstein and power forms are exact", "[formats][roundtrip]") {
  const Geometry_document doc = mixed_document();
  check_same(read_json(write_json(doc)), doc);
  check_same(read_json(write_json(doc, {Json_basis::power, "s", {"p", "q"}})), doc);
  // single objects use the singular keys
  Geometry_document one;
  one.add(doc.patches[0], "single");
  const std::string text = write_json(one);
  CHECK(text.rfind("{\"patch\": ", 0) == 0);
  check_same(read_json(text), one);
  // through files, dispatched by extension
  const std::string path = temp_path("roundtrip.json");
  write_geometry_file(path, doc);
  check_same(read_geometry_file(path), doc);
  std::remove(path.c_str());
  // power form text of the written file matches the patch's own power form (independently evaluated)
  const Geometry_document pw = read_json(write_json(one, {Json_basis::power}));
  for (const Rational& u : {q("0"), q("1/3"), q("2")})
    for (const Rational& v : {q("1"), q("-1/5")}) CHECK(pw.patches[0](u, v) == doc.patches[0](u, v));
}

TEST_CASE("round trips: .dat and .bpt files are exact", "[formats][roundtrip]") {
  // CGAL's Bezier_polycurve.dat example (two polynomial curves of degree 4 and 3)
  const Geometry_document cgal = read_dat("2\n5 0 0 100 10 200 20 300 30 400 40\n4 400 40 500 0 600 100 700 200", "cgal.dat");
  REQUIRE(cgal.curves_2.size() == 2);
  CHECK(cgal.curves_2[0].degree() == 4);
  CHECK(cgal.curves_2[1].control_point(3) == Curve_2::Point{q("700"), q("200")});
  CHECK(write_dat(cgal) == "2\n5  0 0  100 10  200 20  300 30  400 40\n4  400 40  500 0  600 100  700 200\n");
  // exact numbers of every kind, comments
  const Geometry_document d = read_dat("# two curves\n2\n2 1/3 -0.5  0x1p-4 7 # a line\n3 0 0 1e2 1 2.5 0\n", "x.dat");
  REQUIRE(d.curves_2.size() == 2);
  CHECK(d.curves_2[0].control_point(0) == Curve_2::Point{q("1/3"), q("-1/2")});
  CHECK(d.curves_2[0].control_point(1) == Curve_2::Point{q("1/16"), q("7")});
  const std::string dat = temp_path("roundtrip.dat");
  write_geometry_file(dat, d);
  check_same(read_geometry_file(dat), d);
  std::remove(dat.c_str());
  // .bpt
  const Geometry_document teapot = read_geometry_file(shared_data("teapot/teapot32.bpt"));
  const std::string bpt = temp_path("roundtrip.bpt");
  write_geometry_file(bpt, teapot);
  check_same(read_geometry_file(bpt), teapot);
  std::remove(bpt.c_str());
  Geometry_document odd;
  odd.add(Patch(std::vector<std::vector<Patch::Point>>{{{q("1/3"), q("0"), q("1")}, {q("2"), q("1/7"), q("0")}}}));
  CHECK(write_bpt(odd) == "1\n0 1\n1/3 0 1\n2 1/7 0\n");
  check_same(read_bpt(write_bpt(odd)), odd);
  // formats that cannot hold the document say so
  const Geometry_document mixed = mixed_document();
  CHECK_THROWS_AS(write_dat(mixed), Invalid_input);
  CHECK_THROWS_AS(write_bpt(mixed), Invalid_input);
  Geometry_document rational;
  rational.add(mixed.curves_2[0]);
  CHECK_THROWS_AS(write_dat(rational), Invalid_input);
}

TEST_CASE("round trips: Bernstein <-> power <-> file, and subdivision halves reassemble", "[formats][roundtrip]") {
  const Geometry_document doc = mixed_document();
  const Patch& p = doc.patches[0];
  const Patch from_power = Patch::from_power_form(p.power_form(), p.degree_u(), p.degree_v());
  CHECK(from_power == p);
  const Rational t(1, 3);
  // split at u = 1/3: the halves are the restrictions, and extending them by blossoming gives p back
  const auto halves = p.split_u(t);
  CHECK(halves.first == p.restriction(Rational(0), t, Rational(0), Rational(1)));
  CHECK(halves.second == p.restriction(t, Rational(1), Rational(0), Rational(1)));
  CHECK(halves.first.restriction(Rational(0), Rational(3), Rational(0), Rational(1)) == p);
  CHECK(halves.second.restriction(Rational(-1, 2), Rational(1), Rational(0), Rational(1)) == p);
  const auto vh = p.split_v(Rational(1, 2));
  CHECK(vh.first.restriction(Rational(0), Rational(1), Rational(0), Rational(2)) == p);
  // the halves survive the file formats too
  Geometry_document h;
  h.add(halves.first, "left");
  h.add(halves.second, "right");
  check_same(read_json(write_json(h, {Json_basis::power})), h);
  // curves
  const Curve_2& c = doc.curves_2[0];
  const auto ch = c.split(Rational(2, 5));
  CHECK(ch.first.restriction(Rational(0), Rational(5, 2)) == c);
  CHECK(ch.second.restriction(Rational(-2, 3), Rational(1)) == c);
  CHECK(Curve_2::from_power_form(c.power_form(), c.degree()) == c);
}

// ------------------------------------------------------------------------------------- bad input

TEST_CASE("bad JSON input: Parse_error at the offending value", "[formats][errors]") {
  auto json = [](const std::string& text, const std::string& file) { return read_json(text, file); };
  const std::vector<std::pair<std::string, std::string>> table = {
      {"@", "empty file"},
      {"  \n\t @", "empty file"},
      {"{\"curve\": {\"points\": [[0, 0], [1,@", "unexpected end of file"},
      {"{\"curve\": {\"name\": \"abc@", "unexpected end of file in the string"},
      {"{\"curve\": {\"points\": [[0, 0], [1, @abc]]}}", "expected a JSON value"},
      {"{\"curve\": {\"points\": [[0, 0], [1, \"3/@x\"]]}}", "expected a digit"},
      {"{\"curve\": {\"points\": [[0, 0], [1, \"\\u0033/@x\"]]}}", "expected a digit"},
      {"{\"curve\": {\"points\": [[0, 0], [1, @true]]}}", "expected the y coordinate"},
      {"{\"curve\": {\"points\": [[0, 0], [1, @+1]]}}", "expected a JSON value"},
      {"{\"curve\": {\"points\": [[0, 0], [1, 0@x1p3]]}}", "hex floats and fractions must be strings"},
      {"{\"curve\": {\"points\": [[0, 0@7]]}}", "leading zeros"},
      {"{\"curve\": {\"points\": [[0, 0], [\"1e@999999\", 1]]}}", "exponent too large"},
      {"{\"curve\": {\"points\": [[0, 0], [1, \"@1e-3000\"]]}}", "number too large: 9966 bits in its denominator"},
      {"{\"curve\": {\"points\": [[0, 0], [\"@0x1p5000\", 1]]}}", "number too large: 5001 bits in its numerator"},
      {"{\"curve\": {\n  \"degree\": 3,\n  \"points\": @[[0, 0], [1, 1], [2, 0]]\n}}", "expected 4 control points (degree 3), got 3"},
      {"{\"curve\": {\"points\": [[0, 0], [1, 1], [2, 0]],\n \"weights\": @[1, 2]}}", "expected 3 weights"},
      {"{\"curve\": {\"points\": [[0, 0], @[1, 1, 1]]}}", "expected every control point to have 2 coordinates"},
      {"{\"curve\": {\"points\": [@[0]]}}", "expected a control point [x, y] or [x, y, z]"},
      {"{\"curve\": {\"points\": @[]}}", "expected at least one control point"},
      {"{\"curve\": @{\"weights\": [1]}}", "missing key \"points\""},
      {"{\"curve\": {\"points\": [[0, 0], [1, 1], [2, 0]],\n  \"weights\": [1, @0, 1]}}", "the weight is zero"},
      {"{\"curve\": {\"points\": [[0, 0], [1, 1]], \"weights\": [1, @\"-0x0p0\"]}}", "the weight is zero"},
      {"{\"curve\": {\"homogeneous\": true, \"points\": [[1, 0, 0], @[0, 0, 0]]}}", "zero vector"},
      {"{\"curve\": {\"homogeneous\": true, \"points\": [[1, 0, 0]], \"weights\": @[1]}}", "remove \"weights\""},
      {"{\"curve\": {\"points\": [[0, 0]], @\"weigths\": [1]}}", "unknown key \"weigths\""},
      {"{\"curve\": {\"points\": [[0, 0]], @\"points\": [[1, 1]]}}", "duplicate key"},
      {"{\"curve\": {\"basis\": @\"chebyshev\", \"points\": [[0, 0]]}}", "expected the basis"},
      {"@[1, 2]", "expected a JSON object"},
      {"{@\"curvs\": []}", "unknown key"},
      {"{\"curve\": {\"points\": [[0, 0]]}} @x", "after the end of the JSON value"},
      {"{\"curve\": {\"points\": [[0, 0]] @\"name\": \"x\"}}", "expected ',' or '}'"},
      {"{\"curves\": [{\"points\": [[0, 0]]}@}", "expected ',' or ']'"},
      {"{\"curve\": {\"name\": \"a@\nb\"}}", "unexpected line break"},
      {"{\"curve\": {\"name\": \"a@\\qb\"}}", "invalid escape"},
      // patches
      {"{\"patch\": {\"degree\": [1, 1], \"points\": [\n  [[0,0,0],[1,0,0]],\n  @[[0,1,0]]\n]}}", "expected 2 control points in row 1"},
      {"{\"patch\": {\"degree\": [2, 1], \"points\": @[\n  [[0,0,0],[1,0,0]],\n  [[0,1,0],[1,1,0]]\n]}}", "expected 3 rows"},
      {"{\"patch\": {\"points\": [[[0,0,0],@[1,0]]]}}", "expected 3 coordinates"},
      {"{\"patch\": {\"points\": [[[0,0,0],[1,0,0]]], \"weights\": [[1, @\"0/5\"]]}}", "the weight is zero"},
      {"{\"patch\": {\"points\": [[[0,0,0],[1,0,0]]], \"weights\": [@[1]]}}", "expected 2 weights in row 0"},
      {"{\"patch\": {\"degree\": @[1], \"points\": [[[0,0,0]]]}}", "expected the bi-degree"},
      {"{\"patch\": {\"degree\": [1, @-1], \"points\": [[[0,0,0]]]}}", "expected the degree n in v"},
      {"{\"patch\": {\"degree\": [0, 1000000], \"points\": [@[[0,0,0]]]}}", "expected 1000001 control points in row 0"},
      // power basis: expressions
      {"{\"patch\": {\"basis\": \"power\", \"parameters\": [\"s\", \"t\"],\n  \"x\": \"2*s^@\", \"y\": \"s\", \"z\": \"t\"}}",
       "expected a non-negative integer exponent"},
      {"{\"patch\": {\"basis\": \"power\", \"parameters\": [\"s\", \"t\"],\n  \"x\": \"s^@-1\", \"y\": \"s\", \"z\": \"t\"}}",
       "expected a non-negative integer exponent"},
      {"{\"patch\": {\"basis\": \"power\", \"parameters\": [\"s\", \"t\"],\n  \"x\": \"s\", \"y\": \"s + @u*t\", \"z\": \"t\"}}",
       "unknown variable 'u'"},
      {"{\"patch\": {\"basis\": \"power\", \"x\": \"u\", \"y\": \"v\", \"z\": \"u/@v\"}}", "division by a non-constant"},
      {"{\"patch\": {\"basis\": \"power\", \"x\": \"u\", \"y\": \"v\", \"z\": \"(u + v@\"}}", "expected ')'"},
      {"{\"patch\": @{\"basis\": \"power\", \"x\": \"u\", \"y\": \"v\"}}", "missing key \"z\""},
      {"{\"patch\": {\"basis\": \"power\", \"parameters\": [\"s\", @\"s\"], \"x\": \"s\", \"y\": \"s\", \"z\": \"s\"}}",
       "different names"},
      {"{\"patch\": {\"basis\": \"power\", \"x\": \"u\", \"y\": \"v\", \"z\": \"1\", \"w\": @\"u - u\"}}", "identically zero"},
      {"{\"patch\": {\"basis\": \"power\", \"x\": \"u^2\", \"y\": \"v\", \"z\": \"1\", \"degree\": @[1, 1]}}", "does not fit"},
      {"{\"curve\": {\"basis\": \"power\", \"parameter\": \"t\", \"x\": \"t^3\", \"y\": \"t\", \"degree\": @2}}",
       "requested as a Bezier curve of degree 2"},
      {"{\"curve\": {\"basis\": \"power\", \"x\": \"t\", \"y\": @[1]}}", "expected the polynomial y"},
      {"{\"curve\": {\"basis\": \"power\", \"parameter\": @\"2t\", \"x\": \"t\", \"y\": \"t\"}}", "expected a parameter name"},
  };
  for (const auto& row : table) check_parse_error(json, "bad.json", row.first, row.second);

  // a UTF-8 byte order mark is skipped
  CHECK(read_json("\xEF\xBB\xBF{\"curve\": {\"points\": [[0, 0]]}}").curves_2.size() == 1);

  // deeply nested junk: an error at the first bracket that is too deep, no stack overflow
  const std::string deep = std::string(max_json_depth, '[') + "@" + std::string(100000, '[');
  check_parse_error(json, "deep.json", deep, "nested deeper than");
  const std::string deep_objects = [] {
    std::string s;
    for (int i = 0; i < 300; ++i) s += (i == max_json_depth ? "@{\"a\": " : "{\"a\": ");
    return s;
  }();
  check_parse_error(json, "deep.json", deep_objects, "nested deeper than");
}

TEST_CASE("bad .dat and .bpt input: Parse_error at the offending token", "[formats][errors]") {
  auto dat = [](const std::string& text, const std::string& file) { return read_dat(text, file); };
  auto bpt = [](const std::string& text, const std::string& file) { return read_bpt(text, file); };
  const std::vector<std::pair<std::string, std::string>> dat_table = {
      {"@", "empty file"},
      {"# only a comment\n@", "empty file"},
      {"1\n@1000000000000000000 0 0 1 1\n", "expected the number of control points of curve 0 of at most 2"},
      {"@99999999999999999999999999999 1 0 0", "expected the number of curves of at most 1"},
      {"@-1", "expected the number of curves of at least 0"},
      {"1\n2 0 0 @abc 1\n", "expected the x coordinate of control point 1 of curve 0"},
      {"1\n2 0 0 1 1/@0\n", "the denominator is zero"},
      {"1\n@2.5 0 0 1 1\n", "a non-negative integer"},
      {"1\n@0 5 5\n", "of at least 1"},
      {"1\n@-2 0 0 1 1", "of at least 1"},
      {"1\n1 0 0\n@7", "unexpected text after the last of the 1 curves"},
      {"2\n2 0 0 1 1\n@3 1 1 2", "expected the number of control points of curve 1 of at most 1"},
  };
  for (const auto& row : dat_table) check_parse_error(dat, "bad.dat", row.first, row.second);
  const std::vector<std::pair<std::string, std::string>> bpt_table = {
      {"@", "empty file"},
      {"1\n1 @1\n0 0 0\n1 0 0\n0 1 0\n1 1", "expected the degree in v of patch 0 of at most 0"},
      {"1\n@3 3\n0 0 0\n", "expected the degree in u of patch 0 of at most 0"},
      {"@1000000000000000000\n3 3\n0 0 0\n", "expected the number of patches of at most 1"},
      {"1\n@-1 3\n0 0 0", "of at least 0"},
      {"1\n0 0\n1 @foo 3", "expected the y coordinate of control point P[0][0] of patch 0"},
      {"1\n0 0\n1 2 3\n@4", "unexpected text after the last of the 1 patches"},
      {"2\n0 0\n1 2 3\n@1 0\n1 2 3", "expected the degree in u of patch 1 of at most 0"},
  };
  for (const auto& row : bpt_table) check_parse_error(bpt, "bad.bpt", row.first, row.second);
  // truncated copies of the teapot never crash: always a Parse_error
  const std::string teapot = read_text_file(shared_data("teapot/teapot32.bpt"));
  for (std::size_t cut : {std::size_t(1), std::size_t(5), std::size_t(100), teapot.size() / 2, teapot.rfind('\n', teapot.size() - 2)})
    CHECK_THROWS_AS(read_bpt(teapot.substr(0, cut), "cut.bpt"), Parse_error);
}

TEST_CASE("mutated inputs: a Parse_error or a valid document, nothing else", "[formats][errors]") {
  const std::vector<std::pair<std::string, int>> seeds = {
      {read_text_file(source_file("examples/data/circle_arcs.json")), 0},
      {read_text_file(source_file("examples/data/bezoutian_worked_example.json")), 0},
      {"{\"curve\": {\"homogeneous\": true, \"points\": [[1, 0, 0], [0, 1, 2], [2, \"1/3\", 4]]}}", 0},
      {"2\n5 0 0 100 10 200 20 300 30 400 40\n4 400 40 500 0 600 100 700 200", 1},
      {"1\n1 1\n0 0 0\n1 0 0.5\n0 1 0\n1 1 1\n", 2}};
  const std::string alphabet = "{}[]\",:0123456789-+.eE/^*()stuvwxyz \n\\#";
  std::uint32_t state = 20261122;  // a fixed linear congruential sequence: the same inputs every run
  auto next = [&]() { return state = state * 1664525u + 1013904223u, state >> 8; };
  std::size_t parsed = 0, rejected = 0;
  for (int it = 0; it < 1500; ++it) {
    const auto& seed = seeds[next() % seeds.size()];
    std::string s = seed.first;
    for (int k = 1 + next() % 3; k > 0; --k) {
      const std::size_t pos = next() % (s.size() + 1);
      switch (next() % 4) {
        case 0: if (pos < s.size()) s.erase(pos, 1 + next() % 3); break;
        case 1: s.insert(pos, 1, alphabet[next() % alphabet.size()]); break;
        case 2: if (pos < s.size()) s[pos] = alphabet[next() % alphabet.size()]; break;
        default: s.resize(pos);
      }
    }
    try {
      const Geometry_document d = seed.second == 0 ? read_json(s) : seed.second == 1 ? read_dat(s) : read_bpt(s);
      check_same(read_json(write_json(d)), d);
      ++parsed;
    } catch (const Parse_error&) {
      ++rejected;
    }
  }
  CHECK(parsed > 0);
  CHECK(rejected > 0);
}

TEST_CASE("files: missing file and unknown extension", "[formats][errors]") {
  try {
    read_geometry_file(temp_path("does_not_exist.json"));
    FAIL("no error");
  } catch (const Parse_error& e) {
    CHECK(e.line() == 1);
    CHECK(std::string(e.what()).find("cannot open") != std::string::npos);
  }
  CHECK_THROWS_AS(read_geometry_file(shared_data("teapot/README.md")), Parse_error);
  CHECK_THROWS_AS(read_geometry_file(shared_data("teapot")), Parse_error);
  CHECK_THROWS_AS(write_geometry_file(temp_path("x.obj"), Geometry_document()), Invalid_input);
}
