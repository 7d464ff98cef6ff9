// `bezoutian model` on MPI ranks (examples/cli/model_mpi.h). Messages: a worker sends its last result (an empty
// message when it starts) on tag `result_tag`, rank 0 answers with the index of the next problem, or -1 when none
// is left, on tag `work_tag`. A result is JSON text: the problem's status and summary, and the points of each sheet
// of its locus (doubles printed with 17 significant digits, so read back exactly), so that rank 0 chains the curves
// of the model from the same numbers as a threaded run.
#include "exact_json.h"
#include "locus_json.h"
#include "model_mpi.h"

#include <bezoutian/arithmetic/Error.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#if defined(BEZOUTIAN_WITH_MPI)
#include <mpi.h>
#endif

namespace bezoutian_cli {

Problem_summary summarize(const bezoutian::Model_problem& p, bool with_locus) {
  Problem_summary s;
  if (!p.computed) return s;
  const auto& L = p.locus;
  for (const auto& a : L.arcs) {
    bool genuine = false;
    for (const auto& q : a.points) genuine = genuine || q.genuine;
    s.genuine_arcs += genuine;
  }
  for (const auto& c : L.contacts) (c.shared_curve ? s.shared_boundaries : s.contact_points) += 1;
  for (const auto& ip : L.isolated_points) s.touching_points += ip.genuine();
  for (const auto& e : L.edge_lines) s.genuine_edge_lines += e.genuine;
  s.overlaps = L.overlaps.size();
  if (with_locus) s.locus = locus_json(L);
  return s;
}

bool launched_as_mpi_ranks() {
  for (const char* size : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "MPI_LOCALNRANKS", "SLURM_NTASKS"}) {
    const char* v = std::getenv(size);
    if (v && std::atoi(v) > 1) return true;
  }
  return false;
}

#if defined(BEZOUTIAN_WITH_MPI)
namespace {

constexpr int result_tag = 1, work_tag = 2;

std::string encode(std::size_t k, const bezoutian::Model_problem& p, const Problem_summary& s) {
  nlohmann::json sheets = nlohmann::json::array();
  for (std::size_t a = 0; a < p.locus.arcs.size(); ++a)
    for (std::size_t h = 0; h < p.locus.arcs[a].sheets.size(); ++h) {
      nlohmann::json points = nlohmann::json::array();
      for (const auto& q : p.locus.arcs[a].sheets[h].points)
        points.push_back({q.first[0], q.first[1], q.second[0], q.second[1], q.point_3d[0], q.point_3d[1],
                          q.point_3d[2], q.partner[0], q.partner[1]});
      sheets.push_back({{"arc", a}, {"sheet", h}, {"first", p.locus.arcs[a].sheets[h].first}, {"points", points}});
    }
  // the boundary contacts and split points: the exact ends of the pieces, whose links chain_model_curves proves
  nlohmann::json contacts = nlohmann::json::array(), splits = nlohmann::json::array();
  for (const auto& c : p.locus.contacts)
    contacts.push_back({c.side_first, c.side_second, c.shared_curve, algebraic(c.first_0), algebraic(c.first_1),
                        algebraic(c.second_0), algebraic(c.second_1), c.point[0], c.point[1], c.point[2]});
  for (const auto& sp : p.locus.split_points)
    splits.push_back({sp.arc, sp.index, sp.point, sp.coordinate, exact(sp.bound), sp.box[0][0], sp.box[0][1],
                      sp.box[1][0], sp.box[1][1], sp.box[2][0], sp.box[2][1], sp.box[3][0], sp.box[3][1], sp.contact});
  const nlohmann::json j{{"problem", k},
                         {"computed", p.computed},
                         {"error", p.error},
                         {"certified", p.certified},
                         {"reason", p.reason},
                         {"seconds", p.seconds},
                         {"counts",
                          {s.genuine_arcs, s.shared_boundaries, s.contact_points, s.touching_points, s.overlaps,
                           s.genuine_edge_lines}},
                         {"locus", s.locus},
                         {"arcs", p.locus.arcs.size()},
                         {"sheets", sheets},
                         {"contacts", contacts},
                         {"split_points", splits}};
  return j.dump();
}

void decode(const std::string& text, bezoutian::Model_intersection& R, std::vector<Problem_summary>& summaries) {
  const nlohmann::json j = nlohmann::json::parse(text);
  const std::size_t k = j.at("problem").get<std::size_t>();
  bezoutian::Model_problem& p = R.problems.at(k);
  p.computed = j.at("computed").get<bool>();
  p.error = j.at("error").get<std::string>();
  p.certified = j.at("certified").get<bool>();
  p.reason = j.at("reason").get<std::string>();
  p.seconds = j.at("seconds").get<double>();
  Problem_summary& s = summaries.at(k);
  const auto& c = j.at("counts");
  s.genuine_arcs = c.at(0), s.shared_boundaries = c.at(1), s.contact_points = c.at(2), s.touching_points = c.at(3),
  s.overlaps = c.at(4), s.genuine_edge_lines = c.at(5);
  s.locus = j.at("locus");
  p.locus.arcs.resize(j.at("arcs").get<std::size_t>());
  for (const auto& sh : j.at("sheets")) {
    auto& arc = p.locus.arcs.at(sh.at("arc").get<std::size_t>());
    const std::size_t h = sh.at("sheet").get<std::size_t>();
    if (arc.sheets.size() <= h) arc.sheets.resize(h + 1);
    arc.sheets[h].first = sh.at("first").get<std::size_t>();
    for (const auto& q : sh.at("points")) {
      bezoutian::Locus_point x;
      x.first = {q.at(0), q.at(1)};
      x.second = {q.at(2), q.at(3)};
      x.point_3d = {q.at(4), q.at(5), q.at(6)};
      x.partner = {q.at(7), q.at(8)};
      x.genuine = true;
      arc.sheets[h].points.push_back(x);
    }
  }
  for (const auto& c : j.at("contacts")) {
    bezoutian::Boundary_contact x;
    x.side_first = c.at(0), x.side_second = c.at(1), x.shared_curve = c.at(2);
    x.first_0 = algebraic_from_json(c.at(3)), x.first_1 = algebraic_from_json(c.at(4));
    x.second_0 = algebraic_from_json(c.at(5)), x.second_1 = algebraic_from_json(c.at(6));
    x.point = {c.at(7), c.at(8), c.at(9)};
    p.locus.contacts.push_back(x);
  }
  for (const auto& q : j.at("split_points")) {
    bezoutian::Locus_split_point x;
    x.arc = q.at(0), x.index = q.at(1), x.point = q.at(2), x.coordinate = q.at(3);
    x.bound = bezoutian::io::exact_number(q.at(4).get<std::string>());
    for (std::size_t d = 0; d < 4; ++d) x.box[d] = {q.at(5 + 2 * d), q.at(6 + 2 * d)};
    x.contact = q.at(13);
    p.locus.split_points.push_back(x);
  }
}

}  // namespace

bool solve_on_mpi_ranks(const std::vector<bezoutian::Rational_bezier_patch<bezoutian::Rational>>& patches,
                        const bezoutian::Surface_intersection_options& o, bool with_loci,
                        bezoutian::Model_intersection& R, std::vector<Problem_summary>& summaries, int& ranks,
                        const std::function<void(std::size_t, std::size_t)>& progress) {
  struct Session {  // MPI from here to the end of the distribution, on every rank
    Session() {
      int initialized = 0;
      MPI_Initialized(&initialized);
      if (!initialized) MPI_Init(nullptr, nullptr);
    }
    ~Session() { MPI_Finalize(); }
  } session;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (rank != 0) {
    std::string result;  // (empty: ready for the first problem)
    while (true) {
      MPI_Send(result.data(), int(result.size()), MPI_CHAR, 0, result_tag, MPI_COMM_WORLD);
      long long k = -1;
      MPI_Recv(&k, 1, MPI_LONG_LONG, 0, work_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (k < 0) return false;
      bezoutian::Model_problem& p = R.problems.at(std::size_t(k));
      bezoutian::solve_model_problem(patches, p, o);
      result = encode(std::size_t(k), p, summarize(p, with_loci));
      p.locus = bezoutian::Surface_locus();  // (sent: its memory is not kept on this rank)
    }
  }
  summaries.assign(R.problems.size(), Problem_summary());
  std::size_t next = 0, done = 0, bytes = 0;
  for (int active = ranks - 1; active > 0;) {
    // wait without holding a core: rank 0 only hands out work, the other ranks need the cores
    MPI_Status status;
    for (int flag = 0;;) {
      MPI_Iprobe(MPI_ANY_SOURCE, result_tag, MPI_COMM_WORLD, &flag, &status);
      if (flag) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    std::string text(std::size_t(length), '\0');
    MPI_Recv(&text[0], length, MPI_CHAR, status.MPI_SOURCE, result_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    bytes += std::size_t(length);
    if (length > 0) {
      decode(text, R, summaries);
      ++done;
      if (progress) progress(done, R.problems.size());
    }
    long long k = next < R.problems.size() ? (long long)(next++) : -1;
    MPI_Send(&k, 1, MPI_LONG_LONG, status.MPI_SOURCE, work_tag, MPI_COMM_WORLD);
    if (k < 0) --active;
  }
  std::fprintf(stderr, "model: %zu problems solved on %d worker rank(s), %.3g MB of results gathered by rank 0\n",
               done, ranks - 1, double(bytes) / 1e6);
  if (ranks == 1)  // (mpirun -n 1: no worker, rank 0 solves everything itself)
    for (std::size_t k = 0; k < R.problems.size(); ++k) {
      bezoutian::solve_model_problem(patches, R.problems[k], o);
      summaries[k] = summarize(R.problems[k], with_loci);
      if (progress) progress(k + 1, R.problems.size());
    }
  return true;
}

#else

bool solve_on_mpi_ranks(const std::vector<bezoutian::Rational_bezier_patch<bezoutian::Rational>>&,
                        const bezoutian::Surface_intersection_options&, bool, bezoutian::Model_intersection&,
                        std::vector<Problem_summary>&, int&, const std::function<void(std::size_t, std::size_t)>&) {
  throw bezoutian::Invalid_input(
      "model: started as several MPI ranks, but this bezoutian was built without MPI (install libopenmpi-dev and "
      "rebuild; CMake finds it by itself)");
}

#endif

}  // namespace bezoutian_cli
