// Compatibility path: the header lives in the elimination stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_GROEBNER_BIVARIATE_H
#define BEZOUTIAN_FORWARD_GROEBNER_BIVARIATE_H
#include <bezoutian/elimination/Groebner_bivariate.h>
#endif
