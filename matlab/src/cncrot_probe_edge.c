/* [angle, F2] = cncrot_probe_edge(F, E1, E2): see cncrot_probe_edge.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 3, nlhs, 2);
  double f[16], e1[3], e2[3], angle, out[16];
  frame_arg(prhs[0], 1, "F", f);
  point_arg(prhs[1], 2, "E1", e1);
  point_arg(prhs[2], 3, "E2", e2);
  int32_t s = cncrot_probe_edge(f, e1, e2, &angle, out);
  if (s < 0) {
    const char *where = NULL;
    if (s == CNCROT_STATUS_NOT_A_ROTATION) where = label(1, "F");
    else if (s == CNCROT_STATUS_COINCIDENT || s == CNCROT_STATUS_COLLINEAR) where = "the edge (arguments 2 and 3, E1 E2)";
    raise_at(s, where, NULL, -1, 0);
  }
  plhs[0] = mxCreateDoubleScalar(angle);
  if (nlhs > 1) {
    mxArray *fm = mxCreateDoubleMatrix(4, 4, mxREAL);
    frame_to_col_major(out, mxGetDoubles(fm));
    plhs[1] = fm;
  }
}
