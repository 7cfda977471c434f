/* P = cncrot_cl_pose(CL, P0): see cncrot_cl_pose.m. */
#include <string.h>
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 1, 2, nlhs, 1);
  size_t n = rows_arg(prhs[0], 1, "CL", 6);
  const double *d = real_data(prhs[0], 1, "CL");
  /* With P0: each row's frame carried from the row before (the first from P0). */
  int carried = nrhs > 1;
  double before[16];
  if (carried) frame_arg(prhs[1], 2, "P0", before);
  mwSize dims[3] = {4, 4, (mwSize)n};
  mxArray *out = mxCreateNumericArray(3, dims, mxDOUBLE_CLASS, mxREAL);
  double *o = mxGetDoubles(out);
  for (size_t r = 0; r < n; r++) {
    double tip[3] = {d[r], d[r + n], d[r + 2 * n]}, dir[3] = {d[r + 3 * n], d[r + 4 * n], d[r + 5 * n]}, f[16];
    int32_t s = carried ? cncrot_cl_pose_toward(tip, dir, before, f) : cncrot_cl_pose(tip, dir, f);
    if (s < 0) {
      mxDestroyArray(out);
      if (s == CNCROT_STATUS_DEGENERATE) {
        if (n > 1)
          fail("cncrot:badArgument", "%s, row %d: the tool direction (i, j, k) must not be zero", label(1, "CL"), (int)r + 1);
        fail("cncrot:badArgument", "%s: the tool direction (i, j, k) must not be zero", label(1, "CL"));
      }
      /* Only the first row starts from the caller's P0; later ones from the library's. */
      raise_status(s, r == 0 && carried && s != CNCROT_STATUS_NOT_FINITE ? label(2, "P0") : label(1, "CL"), "row", (long)r, n);
    }
    frame_to_col_major(f, o + 16 * r);
    memcpy(before, f, sizeof before);
  }
  plhs[0] = out;
}
