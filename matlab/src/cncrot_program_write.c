/* [line, status] = cncrot_program_write(dialect, form, F, decimals): see cncrot_program_write.m. */
#include "gateway.h"

static const double IDENTITY[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

/* Raises a status of frame k of n, naming what it concerns: what the library refuses with
 * the identity frame and the shortest numbers is the form's, what it refuses with the
 * identity and the decimals is the decimals', the rest the frame's. */
static void raise_write(int32_t s, int32_t dialect, const char *form, int32_t decimals, long k, size_t n) {
  char out[CNCROT_PROGRAM_LINE_MAX + 1];
  char where[160];
  if (cncrot_program_write(dialect, form, IDENTITY, -1, out, sizeof out) == s) {
    char shown[65];
    size_t k;
    for (k = 0; form[k] && k < 64; k++) shown[k] = (unsigned char)form[k] >= 0x20 && (unsigned char)form[k] < 0x7F ? form[k] : '?';
    shown[k] = '\0';
    snprintf(where, sizeof where, "%s '%s'", label(2, "form"), shown);
    if (s == CNCROT_STATUS_BAD_ARGUMENT) {
      /* The forms this dialect writes, by their writer's names. */
      char some[400];
      int len = 0;
      some[0] = '\0';
      for (size_t j = 0; j < COUNT_OF(FORM_TEXTS); j++) {
        if (cncrot_program_write(dialect, FORM_TEXTS[j], IDENTITY, -1, out, sizeof out) < 0) continue;
        if (strstr(some, FORM_TEXTS[j]) != NULL) continue;
        len += snprintf(some + len, sizeof some - len, "%s'%s'", len ? ", " : "", FORM_TEXTS[j]);
      }
      fail("cncrot:badArgument", "%s is not a form this dialect writes: one of %s", where, some);
    }
    raise_at(s, where, NULL, -1, 0);
  }
  if (cncrot_program_write(dialect, form, IDENTITY, decimals, out, sizeof out) == s) {
    if (s == CNCROT_STATUS_BAD_ARGUMENT && decimals > 17)
      fail("cncrot:badArgument", "%s must be 0..17, or negative for the shortest numbers that read back exactly; got %d",
           label(4, "decimals"), (int)decimals);
    raise_at(s, label(4, "decimals"), NULL, -1, 0);
  }
  raise_at(s, label(3, "F"), "frame", k, n);
}

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 4, nlhs, 2);
  int32_t dialect = dialect_arg(prhs[0], 1, "dialect");
  char form[65];
  form_name_arg(prhs[1], 2, form);
  size_t n = squares_arg(prhs[2], 3, "F", 4);
  const double *fd = real_data(prhs[2], 3, "F");
  int32_t decimals = nrhs > 3 ? integer_arg(prhs[3], 4, "decimals") : -1;
  char out[CNCROT_PROGRAM_LINE_MAX + 1];
  int32_t s;
  if (n == 0) {
    /* No frames: the arguments are still the library's to judge. */
    s = cncrot_program_write(dialect, form, IDENTITY, decimals, out, sizeof out);
    if (s < 0 && s != CNCROT_STATUS_NOT_A_ROTATION) raise_write(s, dialect, form, decimals, -1, 0);
  }
  mxArray *lines = mxCreateCellMatrix(n, 1);
  mxArray *st = mxCreateDoubleMatrix(n, 1, mxREAL);
  double *sd = mxGetDoubles(st);
  for (size_t k = 0; k < n; k++) {
    double f[16];
    frame_to_row_major(fd + 16 * k, f);
    s = cncrot_program_write(dialect, form, f, decimals, out, sizeof out);
    if (s < 0) {
      mxDestroyArray(lines);
      mxDestroyArray(st);
      raise_write(s, dialect, form, decimals, (long)k, n);
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
