// Entry functions of the fuzz targets, shared by the libFuzzer drivers (libfuzzer_main_<target>.cpp) and by the
// replay program (replay.cpp) that runs the stored corpus and regression inputs under ctest.
//
// Each function feeds the bytes to one public reader. Returning means the input was read or refused with the
// reader's documented error type; anything else (another exception, a violated invariant) ends the process
// through fuzz_failure(), which libFuzzer and ctest both report as a failure.
#ifndef BEZOUTIAN_FUZZ_TARGETS_H
#define BEZOUTIAN_FUZZ_TARGETS_H

#include <cstddef>
#include <cstdint>
#include <string>

namespace bezoutian {
namespace fuzz {

/// \brief JSON geometry documents: io::read_json() refuses only with Parse_error; what it reads is written by
/// io::write_json() in both bases and read back equal.
void json_document(const std::uint8_t* data, std::size_t size);

/// \brief Polynomial expressions and exact numbers: the first byte picks io::parse_exact_number(),
/// io::parse_polynomial_1() in t or io::parse_polynomial_2() in (s, t); the rest is the text. Refusals are
/// io::Expression_error (numbers: a result with ok == false and an offset inside the text); what is read is
/// printed and read back equal.
void polynomial_expression(const std::uint8_t* data, std::size_t size);

/// \brief CGAL .dat Bezier curves: io::read_dat() refuses only with Parse_error; what it reads is written by
/// io::write_dat() and read back equal.
void cgal_dat(const std::uint8_t* data, std::size_t size);

/// \brief BPT patches: io::read_bpt() refuses only with Parse_error; what it reads is written by io::write_bpt()
/// and read back equal.
void bpt(const std::uint8_t* data, std::size_t size);

/// \brief Planar curve intersections: the bytes decode to one or two rational Bezier curves of degree 1-5 with
/// small coordinates (header byte: self_intersections() or intersect_curves(), polynomial or rational, weights
/// of any sign, coordinate alphabet, method; the second curve independent, a piece of the first, through a point
/// of the first, or the first perturbed), solved with tight Intersection_limits (degree 5, degree product 12,
/// time_limit 2 s).
/// Refusals are Invalid_input, Limit_exceeded and the documented Error of base points and degenerate
/// self-intersection systems. Every reported point and overlap end lies on both curves (exact rational interval
/// evaluation); points are sorted and in [0, 1]^2; both orders of the curves give the same points; a piece of
/// the first curve gives an overlap and a curve through C1(sigma) the point (sigma, 0).
void planar_curves(const std::uint8_t* data, std::size_t size);

/// \brief Surface intersections: the bytes decode to one or two rational Bezier patches of bi-degree at most
/// (2, 2) with small coordinates (header byte: self_intersection_locus() or intersection_locus(), polynomial or
/// rational, weights of any sign, coordinate alphabet; the second patch independent, the first's transposed net,
/// a sub-patch of it, or it with a control point moved), solved with tight limits (degree 2, 64-bit
/// coefficients, time_limit 2 s, no whole-plane analysis). Refusals are Invalid_input, Limit_exceeded and the
/// Error of boundary contacts that the curve engine does not decide. Every
/// traced point proved genuine has both parameter points in [0, 1]^2 (distinct for a self-intersection), a
/// partner enclosure, and one 3D point up to 1e-5 of the patches' size (an evaluation written in the target).
void small_patches(const std::uint8_t* data, std::size_t size);

/// Prints the reason (and the input being replayed, if any) to stderr and aborts.
[[noreturn]] void fuzz_failure(const std::string& reason);

/// Name of the input being replayed, shown by fuzz_failure() ("" under libFuzzer, which names it itself).
std::string& current_input_name();

} // namespace fuzz
} // namespace bezoutian

#endif // BEZOUTIAN_FUZZ_TARGETS_H
