/* Shared by the MEX gateways: argument checks and the mapping of library statuses to MATLAB
 * error identifiers. Errors are raised only here in the gateway, never while the library
 * is running: every library call has returned before mexErrMsgIdAndTxt is reached.
 * Argument checks here are about MATLAB's types and shapes; the values (flags, codes,
 * finiteness, rotations) are the library's to judge. */
#ifndef CNCROT_GATEWAY_H
#define CNCROT_GATEWAY_H

#include <math.h>
#include <stdint.h>
#include <string.h>
#include "mex.h"
#include "cncrot.h"

/* The data of a full real double array of any storage class MATLAB or Octave makes.
 * Octave 7 keeps ranges (1:3), diagonal (eye(3)) and permutation matrices in compact forms
 * whose interleaved-complex accessor mxGetDoubles aborts the whole session (mex.cc:2380);
 * its classic accessor mxGetPr returns the full data for the same objects. MATLAB has no
 * such objects and gets the accessor of its current API. build_mex.m defines CNCROT_OCTAVE. */
static const double *real_data(const mxArray *a, const char *what) {
  if (!mxIsDouble(a)) mexErrMsgIdAndTxt("cncrot:badClass", "%s must be a double array (got %s)", what, mxGetClassName(a));
  if (mxIsSparse(a)) mexErrMsgIdAndTxt("cncrot:badClass", "%s must be a full double array, not sparse (use full())", what);
  if (mxIsComplex(a)) mexErrMsgIdAndTxt("cncrot:complex", "%s must be real", what);
#ifdef CNCROT_OCTAVE
  return mxGetPr(a);
#else
  return mxGetDoubles(a);
#endif
}

static double scalar_arg(const mxArray *a, const char *what) {
  const double *d = real_data(a, what);
  if (mxGetNumberOfElements(a) != 1) mexErrMsgIdAndTxt("cncrot:badSize", "%s must be a scalar", what);
  return d[0];
}

/* A real double scalar holding an integer: flags and codes. Integers beyond int32 are
 * passed on saturated (no flag or code is that large), so that the library names the error
 * (bad flag, bad sequence) rather than the gateway calling 2^31 "not an integer". */
static int32_t integer_arg(const mxArray *a, const char *what) {
  double v = scalar_arg(a, what);
  if (!(v == floor(v))) mexErrMsgIdAndTxt("cncrot:badArgument", "%s must be an integer (got %g)", what, v);
  if (v < -2147483648.0) return INT32_MIN;
  if (v > 2147483647.0) return INT32_MAX;
  return (int32_t)v;
}

/* N-by-cols real double (N >= 0; [] is accepted as 0-by-cols); returns N. */
static size_t rows_arg(const mxArray *a, const char *what, size_t cols) {
  (void)real_data(a, what);
  if (mxGetNumberOfDimensions(a) == 2 && mxGetM(a) == 0 && (mxGetN(a) == cols || mxGetN(a) == 0)) return 0;
  if (mxGetNumberOfDimensions(a) != 2 || mxGetN(a) != cols) {
    const mwSize *d = mxGetDimensions(a);
    mexErrMsgIdAndTxt("cncrot:badSize", "%s must be N-by-%d (got %d-by-%d%s)", what, (int)cols, (int)d[0], (int)d[1],
                      mxGetNumberOfDimensions(a) > 2 ? "-by-..." : "");
  }
  return mxGetM(a);
}

static size_t rows3_arg(const mxArray *a, const char *what) { return rows_arg(a, what, 3); }

/* n-by-n or n-by-n-by-N real double (N >= 0; [] is accepted as none); returns N. */
static size_t squares_arg(const mxArray *a, const char *what, size_t n) {
  (void)real_data(a, what);
  const mwSize *d = mxGetDimensions(a);
  mwSize nd = mxGetNumberOfDimensions(a);
  if (nd == 2 && d[0] == 0 && d[1] == 0) return 0;
  if (nd > 3 || d[0] != n || d[1] != n)
    mexErrMsgIdAndTxt("cncrot:badSize", "%s must be %d-by-%d or %d-by-%d-by-N", what, (int)n, (int)n, (int)n, (int)n);
  return nd == 3 ? d[2] : 1;
}

static size_t matrices_arg(const mxArray *a, const char *what) { return squares_arg(a, what, 3); }

static void raise_status(int32_t s, long row, size_t n);

/* The number of words of a form (the library's table), or the form's error. */
static size_t form_words(int32_t form) {
  size_t count = 0;
  int32_t s = cncrot_form_word_count(form, &count);
  if (s < 0) raise_status(s, -1, 0);
  return count;
}

/* A name: a char row vector (or empty), copied into `out` NUL-terminated. The library
 * judges the characters and the length (it reads at most 32 bytes: a longer name arrives
 * as 32 bytes without NUL and is refused as too long). Characters outside ASCII become a
 * byte the library refuses; an embedded NUL would cut the name silently, so it is refused
 * here. */
static void name_arg(const mxArray *a, const char *what, char out[33]) {
  if (!mxIsChar(a)) mexErrMsgIdAndTxt("cncrot:badClass", "%s must be a char row vector (got %s)", what, mxGetClassName(a));
  size_t n = mxGetNumberOfElements(a);
  if (n > 0 && (mxGetNumberOfDimensions(a) != 2 || mxGetM(a) != 1))
    mexErrMsgIdAndTxt("cncrot:badSize", "%s must be a char row vector, not a char matrix", what);
  const mxChar *c = mxGetChars(a);
  size_t k;
  for (k = 0; k < n && k < 32; k++) {
    unsigned v = (unsigned)c[k];
    if (v == 0) mexErrMsgIdAndTxt("cncrot:badArgument", "%s contains a NUL character", what);
    out[k] = (char)(v > 127 ? 0x80 : v);
  }
  out[k] = '\0';
}

static void check_nargs(int nrhs, int lo, int hi, int nlhs, int out_hi) {
  if (nrhs < lo || nrhs > hi) mexErrMsgIdAndTxt("cncrot:nargin", "wrong number of input arguments");
  if (nlhs > out_hi) mexErrMsgIdAndTxt("cncrot:nargout", "too many output arguments");
}

/* MATLAB's column-major 3x3 (R(i,j) at i + 3j) <-> the library's row-major (at 3i + j). */
static void to_row_major(const double *col, double *row) {
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) row[3 * i + j] = col[i + 3 * j];
}
static void to_col_major(const double *row, double *col) {
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) col[i + 3 * j] = row[3 * i + j];
}

/* The same for 4x4 frames. */
static void frame_to_row_major(const double *col, double *row) {
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++) row[4 * i + j] = col[i + 4 * j];
}
static void frame_to_col_major(const double *row, double *col) {
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++) col[i + 4 * j] = row[4 * i + j];
}

/* Raises the MATLAB error of a negative status (after the library has returned). `row` is
 * the 0-based row of a batch, or -1: it is named only for statuses that belong to one row
 * (a value, not a flag or a code) in a batch of more than one. */
/* The MATLAB error identifier of a status; `per_row` says whether it can differ by row. */
static const char *status_id(int32_t s, int *per_row) {
  const char *id;
  *per_row = 1;
  switch (s) {
    case CNCROT_STATUS_NULL_POINTER: id = "cncrot:nullPointer"; break;
    case CNCROT_STATUS_NOT_FINITE: id = "cncrot:notFinite"; break;
    case CNCROT_STATUS_BAD_FLAG: id = "cncrot:badFlag"; *per_row = 0; break;
    case CNCROT_STATUS_BAD_SEQUENCE: id = "cncrot:badSequence"; *per_row = 0; break;
    case CNCROT_STATUS_INCOMPLETE_SEQUENCE: id = "cncrot:incompleteSequence"; *per_row = 0; break;
    case CNCROT_STATUS_NOT_A_ROTATION: id = "cncrot:notARotation"; break;
    case CNCROT_STATUS_DEGENERATE: id = "cncrot:degenerate"; break;
    case CNCROT_STATUS_BAD_ARGUMENT: id = "cncrot:badArgument"; *per_row = 0; break;
    case CNCROT_STATUS_NOT_AVAILABLE: id = "cncrot:notAvailable"; *per_row = 0; break;
    case CNCROT_STATUS_UNKNOWN_HEAD: id = "cncrot:unknownHead"; break;
    case CNCROT_STATUS_NAME_TOO_LONG: id = "cncrot:nameTooLong"; break;
    case CNCROT_STATUS_PARSE: id = "cncrot:parse"; break;
    case CNCROT_STATUS_TABLE_FULL: id = "cncrot:tableFull"; break;
    case CNCROT_STATUS_OUT_OF_RANGE: id = "cncrot:outOfRange"; break;
    case CNCROT_STATUS_BAD_STATE: id = "cncrot:badState"; break;
    case CNCROT_STATUS_COINCIDENT: id = "cncrot:coincident"; break;
    case CNCROT_STATUS_COLLINEAR: id = "cncrot:collinear"; break;
    case CNCROT_STATUS_TOO_FEW: id = "cncrot:tooFew"; break;
    case CNCROT_STATUS_UNKNOWN_WORD: id = "cncrot:unknownWord"; break;
    case CNCROT_STATUS_NOT_A_NUMBER: id = "cncrot:notANumber"; break;
    case CNCROT_STATUS_MISSING_WORD: id = "cncrot:missingWord"; break;
    case CNCROT_STATUS_LINE_TOO_LONG: id = "cncrot:lineTooLong"; break;
    case CNCROT_STATUS_NO_ROOM: id = "cncrot:noRoom"; break;
    case CNCROT_STATUS_UNREACHABLE: id = "cncrot:unreachable"; break;
    case CNCROT_STATUS_OUT_OF_TRAVEL: id = "cncrot:outOfTravel"; break;
    default: id = "cncrot:internal"; break;
  }
  return id;
}

/* A machine: SINUMERIK swivel-data text (data set 1), or a K-by-12 matrix, one row per
 * axis outermost first: [work_side vx vy vz px py pz min max offset hirth_offset hirth_step].
 * Errors are raised here, after the library has returned. */
static void machine_arg(const mxArray *a, cncrot_machine *m) {
  memset(m, 0, sizeof *m);
  if (mxIsChar(a)) {
    char *t = mxArrayToString(a);
    if (t == NULL) mexErrMsgIdAndTxt("cncrot:badType", "machine text could not be read");
    size_t len = strlen(t);
    int32_t s = cncrot_machine_from_carr(m, t, len, 1), line = 0;
    if (s < 0) cncrot_machine_carr_error_line(t, len, 1, &line);
    mxFree(t);
    if (s < 0) mexErrMsgIdAndTxt(status_id(s, &(int){0}), "swivel data line %d: %s", (int)line, cncrot_status_str(s));
    return;
  }
  size_t k = rows_arg(a, "machine", 12);
  if (k > 3) mexErrMsgIdAndTxt("cncrot:badSize", "machine has at most 3 axes (rows)");
  const double *d = real_data(a, "machine");
  for (size_t r = 0; r < k; r++) {
    double row[12];
    for (int c = 0; c < 12; c++) row[c] = d[r + k * c];
    int32_t side = row[0] == 0 ? 0 : row[0] == 1 ? 1 : 2;
    int32_t s = cncrot_machine_add_axis(m, side, row + 1, row + 4, row[7], row[8]);
    if (s < 0) raise_status(s, (long)r, k);
    m->axes[r].offset_deg = row[9];
    m->axes[r].hirth_offset_deg = row[10];
    m->axes[r].hirth_step_deg = row[11];
  }
}

/* Statuses of a batch call are preset to this, which no status has: a row still holding it
 * was not computed (the call was refused before the rows). */
#define NOT_COMPUTED INT32_MIN

/* After a batch call that returned `r`: raises the first failing row's error (naming the
 * row when there are several), or the refusal's. */
static void raise_batch(int32_t r, const int32_t *st, size_t n) {
  size_t k;
  if (r >= 0) return;
  for (k = 0; k < n; k++)
    if (st[k] < 0 && st[k] != NOT_COMPUTED) raise_status(st[k], (long)k, n);
  raise_status(r, -1, 0);
}

/* An n-by-3 MATLAB array (columns contiguous) as n contiguous rows of 3, and back. */
static void rows_from_columns(const double *in, size_t n, double *rows) {
  size_t k;
  for (k = 0; k < n; k++) {
    rows[3 * k] = in[k];
    rows[3 * k + 1] = in[k + n];
    rows[3 * k + 2] = in[k + 2 * n];
  }
}
static void columns_from_rows(const double *rows, size_t n, double *out) {
  size_t k;
  for (k = 0; k < n; k++) {
    out[k] = rows[3 * k];
    out[k + n] = rows[3 * k + 1];
    out[k + 2 * n] = rows[3 * k + 2];
  }
}

/* A batch's statuses, preset. At least one element, so that a batch of no rows still has
 * valid pointers to pass. */
static int32_t *batch_statuses(size_t n) {
  size_t k, rows = n ? n : 1;
  int32_t *st = (int32_t *)mxMalloc(rows * sizeof(int32_t));
  for (k = 0; k < rows; k++) st[k] = NOT_COMPUTED;
  return st;
}

static void raise_status(int32_t s, long row, size_t n) {
  int per_row;
  const char *id = status_id(s, &per_row);
  if (per_row && row >= 0 && n > 1)
    mexErrMsgIdAndTxt(id, "row %ld: %s", row + 1, cncrot_status_str(s));
  mexErrMsgIdAndTxt(id, "%s", cncrot_status_str(s));
}

#endif
