// Compatibility path: the header lives in the elimination stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_POLYNOMIAL_MATRIX_DETERMINANT_H
#define BEZOUTIAN_FORWARD_POLYNOMIAL_MATRIX_DETERMINANT_H
#include <bezoutian/elimination/Polynomial_matrix_determinant.h>
#endif
