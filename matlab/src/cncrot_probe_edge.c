/* [angle, F2] = cncrot_probe_edge(F, E1, E2): see cncrot_probe_edge.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 3, nlhs, 2);
  if (squares_arg(prhs[0], "F", 4) != 1) mexErrMsgIdAndTxt("cncrot:badSize", "F must be 4-by-4");
  const double *fd = real_data(prhs[0], "F");
  double f[16], e1[3], e2[3], angle, out[16];
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++) f[4 * i + j] = fd[i + 4 * j];
  const mxArray *pts[2] = {prhs[1], prhs[2]};
  double *dst[2] = {e1, e2};
  for (int k = 0; k < 2; k++) {
    const double *d = real_data(pts[k], k ? "E2" : "E1");
    if (mxGetNumberOfElements(pts[k]) != 3) mexErrMsgIdAndTxt("cncrot:badSize", "%s must have 3 elements", k ? "E2" : "E1");
    memcpy(dst[k], d, 3 * sizeof(double));
  }
  int32_t s = cncrot_probe_edge(f, e1, e2, &angle, out);
  if (s < 0) raise_status(s, -1, 0);
  plhs[0] = mxCreateDoubleScalar(angle);
  if (nlhs > 1) {
    mxArray *fm = mxCreateDoubleMatrix(4, 4, mxREAL);
    double *o = mxGetDoubles(fm);
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++) o[i + 4 * j] = out[4 * i + j];
    plhs[1] = fm;
  }
}
