/* [axes, status] = cncrot_program_axes(state, machine, current): see cncrot_program_axes.m. */
#include "program_state.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 2, 3, nlhs, 2);
  cncrot_program p;
  from_struct(prhs[0], 1, &p);
  cncrot_machine m;
  machine_arg(prhs[1], 2, &m);
  double cur[3] = {0, 0, 0}, ax[3];
  if (nrhs > 2) point_arg(prhs[2], 3, "current", cur);
  int32_t s = cncrot_program_axes(&p, &m, cur, ax);
  if (s == CNCROT_STATUS_BAD_ARGUMENT) {
    for (int k = m.count; k < 3; k++)
      if (cur[k] != 0)
        fail("cncrot:badArgument", "%s: the position of axis %d, which the machine does not have, must be 0; got %s",
             label(3, "current"), k + 1, number_text(cur[k]));
  }
  if (s < 0) {
    const char *where = s == CNCROT_STATUS_BAD_STATE ? label(1, "state") : NULL;
    raise_at(s, where, NULL, -1, 0);
  }
  mxArray *a = mxCreateDoubleMatrix(1, 3, mxREAL);
  memcpy(mxGetDoubles(a), ax, sizeof ax);
  plhs[0] = a;
  if (nlhs > 1) plhs[1] = mxCreateDoubleScalar(s);
}
