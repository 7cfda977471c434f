/* [line, status] = cncrot_program_write(dialect, form, F, decimals): see cncrot_program_write.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 4, nlhs, 2);
  int32_t dialect = integer_arg(prhs[0], "dialect");
  char form[65];
  if (!mxIsChar(prhs[1])) mexErrMsgIdAndTxt("cncrot:badClass", "form must be a char row vector");
  size_t m = mxGetNumberOfElements(prhs[1]);
  if (m > 64) mexErrMsgIdAndTxt("cncrot:badArgument", "form is longer than 64 characters");
  const mxChar *c = mxGetChars(prhs[1]);
  for (size_t k = 0; k < m; k++) {
    if (c[k] == 0) mexErrMsgIdAndTxt("cncrot:badArgument", "form contains a NUL character");
    form[k] = (char)(c[k] > 127 ? 0x80 : c[k]);
  }
  form[m] = '\0';
  int32_t decimals = nrhs > 3 ? integer_arg(prhs[3], "decimals") : -1;
  size_t n = squares_arg(prhs[2], "F", 4);
  const double *fd = real_data(prhs[2], "F");
  char out[CNCROT_PROGRAM_LINE_MAX + 1];
  int32_t s;
  if (n == 0) {
    /* No frames: the arguments are still the library's to judge. */
    double id[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    s = cncrot_program_write(dialect, form, id, decimals, out, sizeof out);
    if (s < 0 && s != CNCROT_STATUS_NOT_A_ROTATION) raise_status(s, -1, 0);
  }
  mxArray *lines = mxCreateCellMatrix(n, 1);
  mxArray *st = mxCreateDoubleMatrix(n, 1, mxREAL);
  double *sd = mxGetDoubles(st);
  for (size_t k = 0; k < n; k++) {
    double f[16];
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++) f[4 * i + j] = fd[16 * k + i + 4 * j];
    s = cncrot_program_write(dialect, form, f, decimals, out, sizeof out);
    if (s < 0) {
      mxDestroyArray(lines);
      mxDestroyArray(st);
      raise_status(s, (long)k, n);
    }
    mxSetCell(lines, k, mxCreateString(out));
    sd[k] = s;
  }
  if (n == 1) {
    plhs[0] = mxDuplicateArray(mxGetCell(lines, 0));
    mxDestroyArray(lines);
  } else {
    plhs[0] = lines;
  }
  if (nlhs > 1) plhs[1] = st; else mxDestroyArray(st);
}
