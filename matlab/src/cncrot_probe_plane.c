/* [F, flatness, rms, turned] = cncrot_probe_plane(P, toward): see cncrot_probe_plane.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 1, 2, nlhs, 4);
  size_t n = rows3_arg(prhs[0], 1, "P");
  const double *p = real_data(prhs[0], 1, "P");
  /* The side of Z': the tool's (+Z) by default, a direction, or 'order' (the points'). */
  double toward[3] = {0, 0, 1};
  if (nrhs > 1) {
    size_t len = 0;
    const mxChar *c = chars_of(prhs[1], 2, "toward", &len);
    if (c != NULL) {
      const char *order = "order";
      int same = len == 5;
      for (size_t k = 0; same && k < len; k++) same = (char_code(c[k]) | 0x20) == (unsigned)order[k];
      if (!same) fail("cncrot:badArgument", "%s must be a direction [dx dy dz] or 'order'", label(2, "toward"));
      toward[0] = toward[1] = toward[2] = 0;
    } else {
      point_arg(prhs[1], 2, "toward", toward);
    }
  }
  /* The library reads x y z per point: the N-by-3 column-major array is transposed into a
   * buffer MATLAB owns (freed with the call). */
  double *pts = (double *)mxMalloc((n > 0 ? n : 1) * 3 * sizeof(double));
  rows_from_columns(p, n, pts);
  double f[16], res[2];
  int32_t s = cncrot_probe_plane_toward(pts, n, toward, f, res);
  mxFree(pts);
  int toward_bad = !(isfinite(toward[0]) && isfinite(toward[1]) && isfinite(toward[2]));
  if (s < 0) raise_at(s, s == CNCROT_STATUS_NOT_FINITE && toward_bad ? label(2, "toward") : label(1, "P"), NULL, -1, 0);
  mxArray *fm = mxCreateDoubleMatrix(4, 4, mxREAL);
  frame_to_col_major(f, mxGetDoubles(fm));
  plhs[0] = fm;
  if (nlhs > 1) plhs[1] = mxCreateDoubleScalar(res[0]);
  if (nlhs > 2) plhs[2] = mxCreateDoubleScalar(res[1]);
  if (nlhs > 3) plhs[3] = mxCreateLogicalScalar(s == CNCROT_STATUS_TURNED);
}
