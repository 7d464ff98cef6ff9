// Compatibility path: the header lives in the elimination stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_IMPLICIT_EQUATION_H
#define BEZOUTIAN_FORWARD_IMPLICIT_EQUATION_H
#include <bezoutian/elimination/Implicit_equation.h>
#endif
