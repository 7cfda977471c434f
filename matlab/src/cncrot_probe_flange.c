/* [angles, F] = cncrot_probe_flange(A1, A2, B1, B2): see cncrot_probe_flange.m. */
#include "gateway.h"

static void point_arg(const mxArray *a, const char *what, double p[3]) {
  const double *d = real_data(a, what);
  if (mxGetNumberOfElements(a) != 3) mexErrMsgIdAndTxt("cncrot:badSize", "%s must have 3 elements", what);
  p[0] = d[0];
  p[1] = d[1];
  p[2] = d[2];
}

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 4, 4, nlhs, 2);
  double a1[3], a2[3], b1[3], b2[3], ang[3], f[16];
  point_arg(prhs[0], "A1", a1);
  point_arg(prhs[1], "A2", a2);
  point_arg(prhs[2], "B1", b1);
  point_arg(prhs[3], "B2", b2);
  int32_t s = cncrot_probe_flange(a1, a2, b1, b2, ang, f);
  if (s < 0) raise_status(s, -1, 0);
  mxArray *out = mxCreateDoubleMatrix(1, 3, mxREAL);
  memcpy(mxGetDoubles(out), ang, sizeof ang);
  plhs[0] = out;
  if (nlhs > 1) {
    mxArray *fm = mxCreateDoubleMatrix(4, 4, mxREAL);
    double *fd = mxGetDoubles(fm);
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++) fd[i + 4 * j] = f[4 * i + j];
    plhs[1] = fm;
  }
}
