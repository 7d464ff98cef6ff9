// `bezoutian model` on several processes (mpirun -n K bezoutian model FILE): rank 0 hands out the problems of
// bezoutian::model_problems one at a time to the ranks that ask for work and gathers their results; every other
// rank solves the problems it is given (bezoutian::solve_model_problem) and sends back what the output needs.
#ifndef BEZOUTIAN_CLI_MODEL_MPI_H
#define BEZOUTIAN_CLI_MODEL_MPI_H

#include <bezoutian/intersection/Model_intersection.h>

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace bezoutian_cli {

/// What the model command prints of one problem, computed where the problem was solved: the counts of what it
/// found, and (with --json) its whole locus as JSON.
struct Problem_summary {
  std::size_t genuine_arcs = 0, shared_boundaries = 0, contact_points = 0, touching_points = 0, overlaps = 0,
              genuine_edge_lines = 0;
  nlohmann::json locus;  // null unless asked for
};

/// The summary of a solved problem (with its locus's JSON if `with_locus`).
Problem_summary summarize(const bezoutian::Model_problem& p, bool with_locus);

/// Whether this process was started by an MPI launcher (mpirun, mpiexec, srun) as one of several ranks.
bool launched_as_mpi_ranks();

/// Solves the problems of `R` on the MPI ranks (see the header comment): on rank 0 fills every problem of `R` (its
/// status, error, certification and time, and the sheets of its locus, which the curves of the model are chained
/// from) and `summaries`, and returns true; on the other ranks returns false after their last problem.
/// `progress(done, total)` is called on rank 0. Throws bezoutian::Error if this tool was built without MPI.
bool solve_on_mpi_ranks(const std::vector<bezoutian::Rational_bezier_patch<bezoutian::Rational>>& patches,
                        const bezoutian::Surface_intersection_options& o, bool with_loci,
                        bezoutian::Model_intersection& R, std::vector<Problem_summary>& summaries, int& ranks,
                        const std::function<void(std::size_t, std::size_t)>& progress);

}  // namespace bezoutian_cli

#endif  // BEZOUTIAN_CLI_MODEL_MPI_H
