/* F = cncrot_machine_forward(machine, axes): see cncrot_machine_forward.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 2, 2, nlhs, 1);
  cncrot_machine m;
  machine_arg(prhs[0], 1, &m);
  size_t n = rows3_arg(prhs[1], 2, "axes");
  const double *a = real_data(prhs[1], 2, "axes");
  mwSize dims[3] = {4, 4, (mwSize)n};
  mxArray *out = mxCreateNumericArray(3, dims, mxDOUBLE_CLASS, mxREAL);
  double *o = mxGetDoubles(out);
  for (size_t r = 0; r < n; r++) {
    double ax[3] = {a[r], a[r + n], a[r + 2 * n]}, f[16];
    int32_t s = cncrot_machine_forward(&m, ax, f);
    if (s < 0) {
      mxDestroyArray(out);
      raise_status(s, label(2, "axes"), "row", (long)r, n);
    }
    frame_to_col_major(f, o + 16 * r);
  }
  plhs[0] = out;
}
