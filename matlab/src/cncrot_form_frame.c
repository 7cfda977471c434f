/* F = cncrot_form_frame(form, selector, words): see cncrot_form_frame.m. */
#include "gateway.h"

/* Statuses that concern the selector (_MODE, P, Q, the angle mode), not the words. */
static int selector_status(int32_t s) {
  return s == CNCROT_STATUS_BAD_ARGUMENT || s == CNCROT_STATUS_BAD_SEQUENCE || s == CNCROT_STATUS_INCOMPLETE_SEQUENCE ||
         s == CNCROT_STATUS_NOT_AVAILABLE;
}

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 3, nlhs, 1);
  int32_t form = form_arg(prhs[0], 1, "form");
  int32_t selector = integer_arg(prhs[1], 2, "selector");
  size_t count = form_words(form, 1);
  size_t n = rows_arg(prhs[2], 3, "words", count);
  const double *w = real_data(prhs[2], 3, "words");
  int32_t status;
  if (n == 0) {
    /* No rows: the form and selector are still the library's to accept; errors that
     * depend on the words (zeros are degenerate points) do not apply. */
    double zero[CNCROT_FORM_MAX_WORDS] = {0}, f[16];
    status = cncrot_form_frame(form, selector, zero, count, f);
    if (selector_status(status)) raise_at(status, label(2, "selector"), NULL, -1, 0);
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
      if (selector_status(status)) raise_at(status, label(2, "selector"), NULL, -1, 0);
      raise_status(status, label(3, "words"), "row", (long)k, n);
    }
    frame_to_col_major(f, r + 16 * k);
  }
  plhs[0] = out;
}
