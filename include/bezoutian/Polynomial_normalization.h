// Compatibility path: the header lives in the algebraic stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_POLYNOMIAL_NORMALIZATION_H
#define BEZOUTIAN_FORWARD_POLYNOMIAL_NORMALIZATION_H
#include <bezoutian/algebraic/Polynomial_normalization.h>
#endif
