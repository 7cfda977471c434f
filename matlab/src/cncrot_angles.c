/* [angles, status] = cncrot_angles(intrinsic, sequence, R): see cncrot_angles.m. One call
 * of cncrot_angles_from_matrices for all matrices. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 3, nlhs, 2);
  int32_t intrinsic = convention_arg(prhs[0], 1, "intrinsic");
  int32_t sequence = sequence_arg(prhs[1], 2, "sequence", 1);
  size_t n = matrices_arg(prhs[2], 3, "R");
  const double *r = real_data(prhs[2], 3, "R");
  size_t k, rows = n ? n : 1;
  double *m = (double *)mxCalloc(9 * rows, sizeof(double));
  double *angles = (double *)mxCalloc(3 * rows, sizeof(double));
  int32_t *st = batch_statuses(n);
  for (k = 0; k < n; k++) to_row_major(r + 9 * k, m + 9 * k);
  raise_batch(cncrot_angles_from_matrices(intrinsic, sequence, m, n, angles, st), st, n, label(3, "R"), "matrix");
  mxArray *out = mxCreateDoubleMatrix(n, 3, mxREAL);
  mxArray *sts = mxCreateDoubleMatrix(n, 1, mxREAL);
  double *a = mxGetDoubles(out), *s = mxGetDoubles(sts);
  columns_from_rows(angles, n, a);
  for (k = 0; k < n; k++) s[k] = st[k];
  mxFree(m);
  mxFree(angles);
  mxFree(st);
  plhs[0] = out;
  if (nlhs > 1) plhs[1] = sts; else mxDestroyArray(sts);
}
