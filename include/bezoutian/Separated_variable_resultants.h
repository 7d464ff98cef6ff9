// Compatibility path: the header lives in the elimination stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_SEPARATED_VARIABLE_RESULTANTS_H
#define BEZOUTIAN_FORWARD_SEPARATED_VARIABLE_RESULTANTS_H
#include <bezoutian/elimination/Separated_variable_resultants.h>
#endif
