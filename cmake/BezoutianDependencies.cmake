# Shared by the build tree and the installed package: finds CGAL 5.5, GMP,
# MPFR, MPFI, Boost and nlohmann_json, and attaches them to a target.
include(CMakeFindDependencyMacro)
find_package(CGAL 5.5 REQUIRED)
find_package(Boost 1.70 REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_path(BEZOUTIAN_MPFI_INCLUDE mpfi.h REQUIRED)
find_library(BEZOUTIAN_MPFI_LIB mpfi REQUIRED)
find_library(BEZOUTIAN_MPFR_LIB mpfr REQUIRED)
find_library(BEZOUTIAN_GMP_LIB gmp REQUIRED)
find_library(BEZOUTIAN_GMPXX_LIB gmpxx)

function(bezoutian_link_dependencies target)
  # CGAL_USE_GMP / CGAL_USE_MPFI make CGAL::GMP_arithmetic_kernel (Gmpz, Gmpq,
  # Gmpfi) the default arithmetic kernel instead of CORE; see doc/design.md.
  target_compile_definitions(${target} INTERFACE CGAL_USE_GMP CGAL_USE_MPFI CGAL_USE_MPFR)
  target_include_directories(${target} INTERFACE ${BEZOUTIAN_MPFI_INCLUDE})
  target_link_libraries(${target} INTERFACE CGAL::CGAL Boost::boost nlohmann_json::nlohmann_json
                        ${BEZOUTIAN_MPFI_LIB} ${BEZOUTIAN_MPFR_LIB} ${BEZOUTIAN_GMP_LIB})
endfunction()
