/* [angles, F] = cncrot_probe_flange(A1, A2, B1, B2): see cncrot_probe_flange.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 4, 4, nlhs, 2);
  double a1[3], a2[3], b1[3], b2[3], ang[3], f[16];
  point_arg(prhs[0], 1, "A1", a1);
  point_arg(prhs[1], 2, "A2", a2);
  point_arg(prhs[2], 3, "B1", b1);
  point_arg(prhs[3], 4, "B2", b2);
  int32_t s = cncrot_probe_flange(a1, a2, b1, b2, ang, f);
  if (s < 0) raise_at(s, "the points (arguments 1 to 4, A1 A2 B1 B2)", NULL, -1, 0);
  mxArray *out = mxCreateDoubleMatrix(1, 3, mxREAL);
  memcpy(mxGetDoubles(out), ang, sizeof ang);
  plhs[0] = out;
  if (nlhs > 1) {
    mxArray *fm = mxCreateDoubleMatrix(4, 4, mxREAL);
    frame_to_col_major(f, mxGetDoubles(fm));
    plhs[1] = fm;
  }
}
