/* Shared by the MEX gateways: argument checks and the mapping of library statuses to MATLAB
 * error identifiers. Errors are raised only here in the gateway, never while the library
 * is running: every library call has returned before mexErrMsgIdAndTxt is reached. */
#ifndef CNCROT_GATEWAY_H
#define CNCROT_GATEWAY_H

#include <math.h>
#include <string.h>
#include "mex.h"
#include "cncrot.h"

static void require_real_double(const mxArray *a, const char *what) {
  if (!mxIsDouble(a) || mxIsSparse(a)) mexErrMsgIdAndTxt("cncrot:badClass", "%s must be a double array", what);
  if (mxIsComplex(a)) mexErrMsgIdAndTxt("cncrot:complex", "%s must be real", what);
}

/* A real double scalar holding an integer: flags and codes. Range checks are the library's. */
static int32_t integer_arg(const mxArray *a, const char *what) {
  require_real_double(a, what);
  if (mxGetNumberOfElements(a) != 1) mexErrMsgIdAndTxt("cncrot:badSize", "%s must be a scalar", what);
  double v = mxGetDoubles(a)[0];
  if (!(v == floor(v)) || v < -2147483648.0 || v > 2147483647.0)
    mexErrMsgIdAndTxt("cncrot:badArgument", "%s must be an integer", what);
  return (int32_t)v;
}

static double scalar_arg(const mxArray *a, const char *what) {
  require_real_double(a, what);
  if (mxGetNumberOfElements(a) != 1) mexErrMsgIdAndTxt("cncrot:badSize", "%s must be a scalar", what);
  return mxGetDoubles(a)[0];
}

/* N×3 real double; returns N. */
static size_t rows3_arg(const mxArray *a, const char *what) {
  require_real_double(a, what);
  if (mxGetNumberOfDimensions(a) != 2 || mxGetN(a) != 3 || mxGetM(a) == 0)
    mexErrMsgIdAndTxt("cncrot:badSize", "%s must be N-by-3", what);
  return mxGetM(a);
}

/* 3×3 or 3×3×N real double; returns N. */
static size_t matrices_arg(const mxArray *a, const char *what) {
  require_real_double(a, what);
  const mwSize *d = mxGetDimensions(a);
  mwSize nd = mxGetNumberOfDimensions(a);
  if (nd > 3 || d[0] != 3 || d[1] != 3 || mxGetNumberOfElements(a) == 0)
    mexErrMsgIdAndTxt("cncrot:badSize", "%s must be 3-by-3 or 3-by-3-by-N", what);
  return nd == 3 ? d[2] : 1;
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

/* Raises the MATLAB error of a negative status (after the library has returned). */
static void raise_status(int32_t s, size_t row) {
  const char *id;
  switch (s) {
    case CNCROT_STATUS_NULL_POINTER: id = "cncrot:nullPointer"; break;
    case CNCROT_STATUS_NOT_FINITE: id = "cncrot:notFinite"; break;
    case CNCROT_STATUS_BAD_FLAG: id = "cncrot:badFlag"; break;
    case CNCROT_STATUS_BAD_SEQUENCE: id = "cncrot:badSequence"; break;
    case CNCROT_STATUS_INCOMPLETE_SEQUENCE: id = "cncrot:incompleteSequence"; break;
    case CNCROT_STATUS_NOT_A_ROTATION: id = "cncrot:notARotation"; break;
    case CNCROT_STATUS_DEGENERATE: id = "cncrot:degenerate"; break;
    case CNCROT_STATUS_BAD_ARGUMENT: id = "cncrot:badArgument"; break;
    case CNCROT_STATUS_NOT_AVAILABLE: id = "cncrot:notAvailable"; break;
    case CNCROT_STATUS_UNKNOWN_HEAD: id = "cncrot:unknownHead"; break;
    case CNCROT_STATUS_NAME_TOO_LONG: id = "cncrot:nameTooLong"; break;
    case CNCROT_STATUS_PARSE: id = "cncrot:parse"; break;
    case CNCROT_STATUS_TABLE_FULL: id = "cncrot:tableFull"; break;
    case CNCROT_STATUS_OUT_OF_RANGE: id = "cncrot:outOfRange"; break;
    default: id = "cncrot:internal"; break;
  }
  mexErrMsgIdAndTxt(id, "row %lu: %s", (unsigned long)(row + 1), cncrot_status_str(s));
}

#endif
