/* [words, status] = cncrot_form_values(form, selector, F): see cncrot_form_values.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 3, nlhs, 2);
  int32_t form = integer_arg(prhs[0], "form");
  int32_t selector = integer_arg(prhs[1], "selector");
  size_t count = form_words(form);
  size_t n = squares_arg(prhs[2], "F", 4);
  const double *fd = real_data(prhs[2], "F");
  int32_t status;
  if (n == 0) {
    double id[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, w[CNCROT_FORM_MAX_WORDS];
    status = cncrot_form_values(form, selector, id, w, count);
    if (status < 0) raise_status(status, -1, 0);
  }
  mxArray *out = mxCreateDoubleMatrix(n, count, mxREAL);
  mxArray *st = mxCreateDoubleMatrix(n, 1, mxREAL);
  double *o = mxGetDoubles(out), *s = mxGetDoubles(st);
  for (size_t k = 0; k < n; k++) {
    double f[16], w[CNCROT_FORM_MAX_WORDS];
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++) f[4 * i + j] = fd[16 * k + i + 4 * j];
    status = cncrot_form_values(form, selector, f, w, count);
    if (status < 0) {
      mxDestroyArray(out);
      mxDestroyArray(st);
      raise_status(status, (long)k, n);
    }
    for (size_t j = 0; j < count; j++) o[k + j * n] = w[j];
    s[k] = status;
  }
  plhs[0] = out;
  if (nlhs > 1) plhs[1] = st; else mxDestroyArray(st);
}
