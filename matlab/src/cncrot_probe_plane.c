/* [F, flatness, rms] = cncrot_probe_plane(P): see cncrot_probe_plane.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 1, 1, nlhs, 3);
  size_t n = rows3_arg(prhs[0], 1, "P");
  const double *p = real_data(prhs[0], 1, "P");
  /* The library reads x y z per point: the N-by-3 column-major array is transposed into a
   * buffer MATLAB owns (freed with the call). */
  double *pts = (double *)mxMalloc((n > 0 ? n : 1) * 3 * sizeof(double));
  rows_from_columns(p, n, pts);
  double f[16], res[2];
  int32_t s = cncrot_probe_plane(pts, n, f, res);
  mxFree(pts);
  if (s < 0) raise_at(s, label(1, "P"), NULL, -1, 0);
  mxArray *fm = mxCreateDoubleMatrix(4, 4, mxREAL);
  frame_to_col_major(f, mxGetDoubles(fm));
  plhs[0] = fm;
  if (nlhs > 1) plhs[1] = mxCreateDoubleScalar(res[0]);
  if (nlhs > 2) plhs[2] = mxCreateDoubleScalar(res[1]);
}
