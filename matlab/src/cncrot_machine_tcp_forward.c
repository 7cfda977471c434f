/* P = cncrot_machine_tcp_forward(machine, axes, L): see cncrot_machine_tcp_forward.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 3, nlhs, 1);
  cncrot_machine m;
  machine_arg(prhs[0], 1, &m);
  size_t n = rows_arg(prhs[1], 2, "axes", 6);
  const double *a = real_data(prhs[1], 2, "axes");
  double len = finite_arg(scalar_arg(prhs[2], 3, "L"), 3, "L");
  mwSize dims[3] = {4, 4, (mwSize)n};
  mxArray *out = mxCreateNumericArray(3, dims, mxDOUBLE_CLASS, mxREAL);
  double *o = mxGetDoubles(out);
  for (size_t r = 0; r < n; r++) {
    double ax[6], f[16];
    for (int c = 0; c < 6; c++) ax[c] = a[r + n * c];
    int32_t s = cncrot_machine_tcp_forward(&m, ax, len, f);
    if (s < 0) {
      mxDestroyArray(out);
      raise_status(s, s == CNCROT_STATUS_OUT_OF_RANGE && !(len >= -1e6 && len <= 1e6) ? label(3, "L") : label(2, "axes"),
                   "row", (long)r, n);
    }
    frame_to_col_major(f, o + 16 * r);
  }
  plhs[0] = out;
}
