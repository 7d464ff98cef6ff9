// Compatibility path: the header lives in the elimination stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_BEZOUT_MATRIX_H
#define BEZOUTIAN_FORWARD_BEZOUT_MATRIX_H
#include <bezoutian/elimination/Bezout_matrix.h>
#endif
