// Deliberately unguarded include cycle (a -> b -> a) for the include-cycle test.
#include "ffx_dof_test_cycle_b.h"
