/* P = cncrot_cl_pose(CL): see cncrot_cl_pose.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 1, 1, nlhs, 1);
  size_t n = rows_arg(prhs[0], 1, "CL", 6);
  const double *d = real_data(prhs[0], 1, "CL");
  mwSize dims[3] = {4, 4, (mwSize)n};
  mxArray *out = mxCreateNumericArray(3, dims, mxDOUBLE_CLASS, mxREAL);
  double *o = mxGetDoubles(out);
  for (size_t r = 0; r < n; r++) {
    double tip[3] = {d[r], d[r + n], d[r + 2 * n]}, dir[3] = {d[r + 3 * n], d[r + 4 * n], d[r + 5 * n]}, f[16];
    int32_t s = cncrot_cl_pose(tip, dir, f);
    if (s < 0) {
      mxDestroyArray(out);
      if (s == CNCROT_STATUS_DEGENERATE) {
        if (n > 1)
          fail("cncrot:badArgument", "%s, row %d: the tool direction (i, j, k) must not be zero", label(1, "CL"), (int)r + 1);
        fail("cncrot:badArgument", "%s: the tool direction (i, j, k) must not be zero", label(1, "CL"));
      }
      raise_status(s, label(1, "CL"), "row", (long)r, n);
    }
    frame_to_col_major(f, o + 16 * r);
  }
  plhs[0] = out;
}
