/* R = cncrot_matrix(intrinsic, sequence, angles): see cncrot_matrix.m. One call of
 * cncrot_matrices_from_angles for all rows. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 3, nlhs, 1);
  int32_t intrinsic = convention_arg(prhs[0], 1, "intrinsic");
  int32_t sequence = sequence_arg(prhs[1], 2, "sequence", 0);
  size_t n = rows3_arg(prhs[2], 3, "angles");
  const double *in = real_data(prhs[2], 3, "angles");
  size_t k, rows = n ? n : 1;
  double *a = (double *)mxCalloc(3 * rows, sizeof(double));
  double *m = (double *)mxCalloc(9 * rows, sizeof(double));
  int32_t *st = batch_statuses(n);
  rows_from_columns(in, n, a);
  raise_batch(cncrot_matrices_from_angles(intrinsic, sequence, a, n, m, st), st, n, label(3, "angles"), "row");
  mwSize dims[3] = {3, 3, (mwSize)n};
  mxArray *out = mxCreateNumericArray(n == 1 ? 2 : 3, dims, mxDOUBLE_CLASS, mxREAL);
  double *r = mxGetDoubles(out);
  for (k = 0; k < n; k++) to_col_major(m + 9 * k, r + 9 * k);
  mxFree(a);
  mxFree(m);
  mxFree(st);
  plhs[0] = out;
}
