/* [words, status] = cncrot_form_values(form, selector, F): see cncrot_form_values.m. */
#include "gateway.h"

static const double IDENTITY[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

/* Raises a status of frame k of n: what the form and selector refuse of any frame (the
 * identity's status says so) concerns them, the rest the frame. */
static void raise_values(int32_t s, int32_t form, int32_t selector, size_t count, long k, size_t n) {
  double w[CNCROT_FORM_MAX_WORDS];
  int32_t t = cncrot_form_values(form, selector, IDENTITY, w, count);
  if (t == s) raise_at(s, "arguments 1 and 2 (form and selector)", NULL, -1, 0);
  raise_at(s, label(3, "F"), "frame", k, n);
}

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 3, nlhs, 2);
  int32_t form = form_arg(prhs[0], 1, "form");
  int32_t selector = integer_arg(prhs[1], 2, "selector");
  size_t count = form_words(form, 1);
  size_t n = squares_arg(prhs[2], 3, "F", 4);
  const double *fd = real_data(prhs[2], 3, "F");
  int32_t status;
  if (n == 0) {
    double w[CNCROT_FORM_MAX_WORDS];
    status = cncrot_form_values(form, selector, IDENTITY, w, count);
    if (status < 0) raise_at(status, "arguments 1 and 2 (form and selector)", NULL, -1, 0);
  }
  mxArray *out = mxCreateDoubleMatrix(n, count, mxREAL);
  mxArray *st = mxCreateDoubleMatrix(n, 1, mxREAL);
  double *o = mxGetDoubles(out), *s = mxGetDoubles(st);
  for (size_t k = 0; k < n; k++) {
    double f[16], w[CNCROT_FORM_MAX_WORDS];
    frame_to_row_major(fd + 16 * k, f);
    status = cncrot_form_values(form, selector, f, w, count);
    if (status < 0) {
      mxDestroyArray(out);
      mxDestroyArray(st);
      raise_values(status, form, selector, count, (long)k, n);
    }
    for (size_t j = 0; j < count; j++) o[k + j * n] = w[j];
    s[k] = status;
  }
  plhs[0] = out;
  if (nlhs > 1) plhs[1] = st; else mxDestroyArray(st);
}
