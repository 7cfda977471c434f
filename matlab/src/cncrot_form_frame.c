/* F = cncrot_form_frame(form, selector, words): see cncrot_form_frame.m. */
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 3, nlhs, 1);
  int32_t form = integer_arg(prhs[0], "form");
  int32_t selector = integer_arg(prhs[1], "selector");
  size_t count = form_words(form);
  size_t n = rows_arg(prhs[2], "words", count);
  const double *w = real_data(prhs[2], "words");
  int32_t status;
  if (n == 0) {
    /* No rows: the form and selector are still the library's to accept; errors that
     * depend on the words (zeros are degenerate points) do not apply. */
    double zero[CNCROT_FORM_MAX_WORDS] = {0}, f[16];
    status = cncrot_form_frame(form, selector, zero, count, f);
    if (status == CNCROT_STATUS_BAD_ARGUMENT || status == CNCROT_STATUS_BAD_SEQUENCE ||
        status == CNCROT_STATUS_INCOMPLETE_SEQUENCE || status == CNCROT_STATUS_NOT_AVAILABLE)
      raise_status(status, -1, 0);
  }
  mwSize dims[3] = {4, 4, (mwSize)n};
  mxArray *out = mxCreateNumericArray(n == 1 ? 2 : 3, dims, mxDOUBLE_CLASS, mxREAL);
  double *r = mxGetDoubles(out);
  for (size_t k = 0; k < n; k++) {
    double words[CNCROT_FORM_MAX_WORDS], f[16];
    for (size_t j = 0; j < count; j++) words[j] = w[k + j * n];
    status = cncrot_form_frame(form, selector, words, count, f);
    if (status < 0) {
      mxDestroyArray(out);
      raise_status(status, (long)k, n);
    }
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++) r[16 * k + i + 4 * j] = f[4 * i + j];
  }
  plhs[0] = out;
}
