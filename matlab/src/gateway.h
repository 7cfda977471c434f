/* Shared by the MEX gateways: reading MATLAB's arguments (numbers, names of conventions,
 * dialects, rules and forms), and raising MATLAB errors.
 *
 * Errors are raised only here in the gateway, never while the library is running: every
 * library call has returned before mexErrMsgIdAndTxt is reached. A message says which
 * argument was wrong and what it must be ("cncrot_convert: argument 2 (sequence_in) must
 * be an axis sequence such as 'ZXY' or a code 0..63; got 'ZQY'"); the identifier carries
 * the library's status (cncrot:badSequence). Argument checks here are about MATLAB's types
 * and shapes and about names; the values of numbers (flags, codes, finiteness, rotations)
 * are the library's to judge: a flag or code is checked by a call of the library, so that
 * its error can name the argument. */
#ifndef CNCROT_GATEWAY_H
#define CNCROT_GATEWAY_H

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "mex.h"
#include "cncrot.h"

/* ------------------------------------------------------------------------------------ */
/* Errors                                                                                */

/* Raises a MATLAB error whose message reads "<function>: <message>". Octave's
 * mexErrMsgIdAndTxt puts "<function>: " before the message itself; MATLAB's does not
 * (build_mex.m defines CNCROT_OCTAVE). */
static void fail(const char *id, const char *fmt, ...) {
  char msg[1200];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
#ifdef CNCROT_OCTAVE
  mexErrMsgIdAndTxt(id, "%s", msg);
#else
  mexErrMsgIdAndTxt(id, "%s: %s", mexFunctionName(), msg);
#endif
}

/* "argument 2 (sequence_in)"; for pos 0 the name alone (a field: "previous gud.CYC600_5").
 * Four rotating buffers: a message may hold more than one. */
static const char *label(int pos, const char *name) {
  static char buf[4][128];
  static unsigned next;
  char *b = buf[next++ & 3u];
  if (pos > 0) snprintf(b, sizeof buf[0], "argument %d (%s)", pos, name);
  else snprintf(b, sizeof buf[0], "%s", name);
  return b;
}

/* The MATLAB error identifier of a status. */
static const char *status_id(int32_t s) {
  switch (s) {
    case CNCROT_STATUS_NULL_POINTER: return "cncrot:nullPointer";
    case CNCROT_STATUS_NOT_FINITE: return "cncrot:notFinite";
    case CNCROT_STATUS_BAD_FLAG: return "cncrot:badFlag";
    case CNCROT_STATUS_BAD_SEQUENCE: return "cncrot:badSequence";
    case CNCROT_STATUS_INCOMPLETE_SEQUENCE: return "cncrot:incompleteSequence";
    case CNCROT_STATUS_NOT_A_ROTATION: return "cncrot:notARotation";
    case CNCROT_STATUS_DEGENERATE: return "cncrot:degenerate";
    case CNCROT_STATUS_BAD_ARGUMENT: return "cncrot:badArgument";
    case CNCROT_STATUS_NOT_AVAILABLE: return "cncrot:notAvailable";
    case CNCROT_STATUS_UNKNOWN_HEAD: return "cncrot:unknownHead";
    case CNCROT_STATUS_NAME_TOO_LONG: return "cncrot:nameTooLong";
    case CNCROT_STATUS_PARSE: return "cncrot:parse";
    case CNCROT_STATUS_TABLE_FULL: return "cncrot:tableFull";
    case CNCROT_STATUS_OUT_OF_RANGE: return "cncrot:outOfRange";
    case CNCROT_STATUS_BAD_STATE: return "cncrot:badState";
    case CNCROT_STATUS_COINCIDENT: return "cncrot:coincident";
    case CNCROT_STATUS_COLLINEAR: return "cncrot:collinear";
    case CNCROT_STATUS_TOO_FEW: return "cncrot:tooFew";
    case CNCROT_STATUS_UNKNOWN_WORD: return "cncrot:unknownWord";
    case CNCROT_STATUS_NOT_A_NUMBER: return "cncrot:notANumber";
    case CNCROT_STATUS_MISSING_WORD: return "cncrot:missingWord";
    case CNCROT_STATUS_LINE_TOO_LONG: return "cncrot:lineTooLong";
    case CNCROT_STATUS_NO_ROOM: return "cncrot:noRoom";
    case CNCROT_STATUS_UNREACHABLE: return "cncrot:unreachable";
    case CNCROT_STATUS_OUT_OF_TRAVEL: return "cncrot:outOfTravel";
    case CNCROT_STATUS_HAS_ORIGIN: return "cncrot:hasOrigin";
    default: return "cncrot:internal";
  }
}

/* Whether a status can differ from row to row of a batch (a value), rather than belonging
 * to the whole call (a flag, a code, an option). */
static int status_per_row(int32_t s) {
  return !(s == CNCROT_STATUS_BAD_FLAG || s == CNCROT_STATUS_BAD_SEQUENCE ||
           s == CNCROT_STATUS_INCOMPLETE_SEQUENCE || s == CNCROT_STATUS_BAD_ARGUMENT ||
           s == CNCROT_STATUS_NOT_AVAILABLE);
}

/* The library's text of a status without the C name before it ("CNCROT_STATUS_NOT_FINITE:
 * a number is NaN or infinite" -> "a number is NaN or infinite"): the identifier names
 * the status. */
static const char *status_text(int32_t s) {
  const char *t = cncrot_status_str(s);
  const char *c = strstr(t, ": ");
  return (strncmp(t, "CNCROT_STATUS_", 14) == 0 && c) ? c + 2 : t;
}

/* Raises the error of a negative status (after the library has returned). `where` names
 * what it concerns ("argument 3 (angles)", or NULL); `unit` and `row` (0-based, or -1) name
 * one element of a batch of n > 1 ("row", "matrix", "frame", "line"). */
static void raise_at(int32_t s, const char *where, const char *unit, long row, size_t n) {
  const char *id = status_id(s), *text = status_text(s);
  int named = row >= 0 && n > 1 && unit != NULL;
  if (where && named) fail(id, "%s, %s %ld: %s", where, unit, row + 1, text);
  if (named) fail(id, "%s %ld: %s", unit, row + 1, text);
  if (where) fail(id, "%s: %s", where, text);
  fail(id, "%s", text);
}

/* The same, naming the row only for statuses that belong to one row. */
static void raise_status(int32_t s, const char *where, const char *unit, long row, size_t n) {
  raise_at(s, where, unit, status_per_row(s) ? row : -1, n);
}

static void check_nargs(int nrhs, int lo, int hi, int nlhs, int out_hi) {
  char expected[32];
  if (lo == hi) snprintf(expected, sizeof expected, "%d", lo);
  else snprintf(expected, sizeof expected, "%d to %d", lo, hi);
  if (nrhs < lo) fail("cncrot:nargin", "not enough input arguments: expects %s, got %d (see help %s)", expected, nrhs, mexFunctionName());
  if (nrhs > hi) fail("cncrot:nargin", "too many input arguments: expects %s, got %d (see help %s)", expected, nrhs, mexFunctionName());
  if (nlhs > out_hi) fail("cncrot:nargout", "too many output arguments: at most %d, asked for %d", out_hi, nlhs);
}

/* ------------------------------------------------------------------------------------ */
/* Text: char row vectors, and MATLAB's string scalars                                   */

/* The characters of a char row vector ('' of any empty size included) or of a string
 * scalar ("..." in MATLAB; Octave's "..." is char), in *n; NULL when `a` is no text. A char
 * matrix or a string array of other than one element is refused (badSize). A string is
 * converted by MATLAB's char; the copy is freed by MATLAB when the MEX function returns. */
static const mxChar *chars_of(const mxArray *a, int pos, const char *name, size_t *n) {
  if (mxIsClass(a, "string")) {
    if (mxGetNumberOfElements(a) != 1)
      fail("cncrot:badSize", "%s must be one text (a char row vector or a string scalar), not a string array of %d elements",
           label(pos, name), (int)mxGetNumberOfElements(a));
    mxArray *c = NULL, *in = (mxArray *)a;
    mxArray *trap = mexCallMATLABWithTrap(1, &c, 1, &in, "char");
    if (trap != NULL || c == NULL || !mxIsChar(c))
      fail("cncrot:badClass", "%s: the string could not be read (a missing string?)", label(pos, name));
    a = c;
  }
  if (!mxIsChar(a)) return NULL;
  *n = mxGetNumberOfElements(a);
  if (*n > 0 && (mxGetNumberOfDimensions(a) != 2 || mxGetM(a) != 1))
    fail("cncrot:badSize", "%s must be a char row vector, not a char matrix", label(pos, name));
  return mxGetChars(a);
}

/* A character's code: MATLAB's mxChar is a UTF-16 unit, Octave's a byte (char, signed on
 * x86-64) of UTF-8. */
static unsigned char_code(mxChar c) { return sizeof(mxChar) == 1 ? (unsigned)(unsigned char)c : (unsigned)c; }

/* ASCII as it is; anything else as 0x80, a byte the library refuses in names and lines. */
static char ascii_byte(mxChar c) { return (char)(char_code(c) > 127 ? 0x80 : char_code(c)); }

/* Unicode code points of text: MATLAB's mxChar is UTF-16, Octave's is a byte of UTF-8. At
 * most `cap` are stored; the count of all is returned. Malformed input gives U+FFFD. */
static size_t code_points(const mxChar *c, size_t n, uint32_t *out, size_t cap) {
  size_t k = 0, count = 0;
  while (k < n) {
    uint32_t u;
    if (sizeof(mxChar) == 1) {
      unsigned b = (unsigned char)c[k++];
      int more = b < 0x80 ? 0 : (b & 0xE0) == 0xC0 ? 1 : (b & 0xF0) == 0xE0 ? 2 : (b & 0xF8) == 0xF0 ? 3 : -1;
      u = more == 0 ? b : more == 1 ? (b & 0x1F) : more == 2 ? (b & 0x0F) : (b & 0x07);
      if (more < 0) u = 0xFFFD;
      for (int j = 0; j < more; j++) {
        if (k >= n || ((unsigned char)c[k] & 0xC0) != 0x80) {
          u = 0xFFFD;
          break;
        }
        u = (u << 6) | ((unsigned char)c[k++] & 0x3F);
      }
    } else {
      u = (uint32_t)c[k++];
      if (u >= 0xD800 && u < 0xDC00 && k < n && (uint32_t)c[k] >= 0xDC00 && (uint32_t)c[k] < 0xE000)
        u = 0x10000 + ((u - 0xD800) << 10) + ((uint32_t)c[k++] - 0xDC00);
    }
    if (count < cap) out[count] = u;
    count++;
  }
  return count;
}

/* Text for a message: 'ZQY' in quotes, at most 40 characters, as UTF-8. */
static const char *quoted(const uint32_t *u, size_t n, size_t stored) {
  static char buf[4][200];
  static unsigned next;
  char *b = buf[next++ & 3u], *p = b;
  *p++ = '\'';
  for (size_t k = 0; k < stored && k < 40; k++) {
    uint32_t c = u[k];
    if (c < 0x20 || c == 0x7F) c = '?';
    if (c < 0x80) *p++ = (char)c;
    else if (c < 0x800) {
      *p++ = (char)(0xC0 | (c >> 6));
      *p++ = (char)(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
      *p++ = (char)(0xE0 | (c >> 12));
      *p++ = (char)(0x80 | ((c >> 6) & 0x3F));
      *p++ = (char)(0x80 | (c & 0x3F));
    } else {
      *p++ = (char)(0xF0 | (c >> 18));
      *p++ = (char)(0x80 | ((c >> 12) & 0x3F));
      *p++ = (char)(0x80 | ((c >> 6) & 0x3F));
      *p++ = (char)(0x80 | (c & 0x3F));
    }
  }
  if (n > 40 || n > stored) p += sprintf(p, "...");
  *p++ = '\'';
  *p = '\0';
  return b;
}

/* A value that is not what was asked for, for a message: "a 1-by-3 double", "a cell". */
static const char *described(const mxArray *a) {
  static char buf[160];
  const mwSize *d = mxGetDimensions(a);
  size_t nd = mxGetNumberOfDimensions(a);
  int len = snprintf(buf, sizeof buf, "a %d", (int)d[0]);
  /* Every dimension (4-by-4-by-2), the first few of an array of many. */
  for (size_t k = 1; k < nd && k < 8 && len > 0 && len < (int)sizeof buf; k++)
    len += snprintf(buf + len, sizeof buf - len, "-by-%d", (int)d[k]);
  if (nd > 8 && len > 0 && len < (int)sizeof buf) len += snprintf(buf + len, sizeof buf - len, "-by-...");
  if (len > 0 && len < (int)sizeof buf)
    snprintf(buf + len, sizeof buf - len, " %s%s", mxIsSparse(a) ? "sparse " : "", mxGetClassName(a));
  return buf;
}

/* A name: text copied into `out` NUL-terminated, as bytes. The library judges the
 * characters and the length (it reads at most 32 bytes: a longer name arrives as 32 bytes
 * without NUL and is refused as too long). Characters outside ASCII become a byte the
 * library refuses; an embedded NUL would cut the name silently, so it is refused here. */
static void name_arg(const mxArray *a, int pos, const char *name, char out[33]) {
  size_t n = 0;
  const mxChar *c = chars_of(a, pos, name, &n);
  if (c == NULL) fail("cncrot:badClass", "%s must be text (a char row vector or a string); got %s", label(pos, name), described(a));
  size_t k;
  for (k = 0; k < n && k < 32; k++) {
    if (char_code(c[k]) == 0) fail("cncrot:badArgument", "%s contains a NUL character", label(pos, name));
    out[k] = ascii_byte(c[k]);
  }
  out[k] = '\0';
}

/* ------------------------------------------------------------------------------------ */
/* Numbers                                                                               */

/* The data of a full real double array of any storage class MATLAB or Octave makes.
 * Octave 7 keeps ranges (1:3), diagonal (eye(3)) and permutation matrices in compact forms
 * whose interleaved-complex accessor mxGetDoubles aborts the whole session (mex.cc:2380);
 * its classic accessor mxGetPr returns the full data for the same objects. MATLAB has no
 * such objects and gets the accessor of its current API. build_mex.m defines CNCROT_OCTAVE. */
static const double *real_data(const mxArray *a, int pos, const char *name) {
  if (!mxIsDouble(a)) fail("cncrot:badClass", "%s must be a double array; got %s", label(pos, name), described(a));
  if (mxIsSparse(a)) fail("cncrot:badClass", "%s must be a full double array, not sparse (use full())", label(pos, name));
  if (mxIsComplex(a)) fail("cncrot:complex", "%s must be real", label(pos, name));
#ifdef CNCROT_OCTAVE
  return mxGetPr(a);
#else
  return mxGetDoubles(a);
#endif
}

static double scalar_arg(const mxArray *a, int pos, const char *name) {
  const double *d = real_data(a, pos, name);
  if (mxGetNumberOfElements(a) != 1) fail("cncrot:badSize", "%s must be a scalar; got %s", label(pos, name), described(a));
  return d[0];
}

/* A number for a message: integers exactly, NaN and Inf by name. */
static const char *number_text(double v) {
  static char buf[4][48];
  static unsigned next;
  char *b = buf[next++ & 3u];
  if (v != v) snprintf(b, sizeof buf[0], "NaN");
  else if (isinf(v)) snprintf(b, sizeof buf[0], v > 0 ? "Inf" : "-Inf");
  else snprintf(b, sizeof buf[0], "%.15g", v);
  return b;
}

/* A real scalar holding an integer, of any numeric class (double, single, int8 .. uint64)
 * or logical: flags, codes, selectors. `expect` says what the argument must be, for the
 * messages. A fraction, NaN is refused as cncrot:badArgument; an integer beyond int32
 * (no flag or code is that large) with `range_id`, the identifier of the library's error
 * for that argument (cncrot:badFlag for a flag). */
static int32_t integer_arg_as(const mxArray *a, int pos, const char *name, const char *expect, const char *range_id) {
  if (!mxIsNumeric(a) && !mxIsLogical(a))
    fail("cncrot:badClass", "%s must be %s; got %s", label(pos, name), expect, described(a));
  if (mxIsSparse(a)) fail("cncrot:badClass", "%s must be a full scalar, not sparse (use full())", label(pos, name));
  if (mxIsComplex(a)) fail("cncrot:complex", "%s must be real", label(pos, name));
  if (mxGetNumberOfElements(a) != 1) fail("cncrot:badSize", "%s must be a scalar; got %s", label(pos, name), described(a));
  double v;
  int64_t i = 0;
  int exact = 0; /* the 64-bit classes: compared as integers, not through a double */
  switch (mxGetClassID(a)) {
    case mxDOUBLE_CLASS: v = real_data(a, pos, name)[0]; break;
    case mxSINGLE_CLASS: v = *(const float *)mxGetData(a); break;
    case mxLOGICAL_CLASS: v = mxGetLogicals(a)[0] ? 1 : 0; break;
    case mxINT8_CLASS: v = *(const int8_t *)mxGetData(a); break;
    case mxUINT8_CLASS: v = *(const uint8_t *)mxGetData(a); break;
    case mxINT16_CLASS: v = *(const int16_t *)mxGetData(a); break;
    case mxUINT16_CLASS: v = *(const uint16_t *)mxGetData(a); break;
    case mxINT32_CLASS: v = *(const int32_t *)mxGetData(a); break;
    case mxUINT32_CLASS: v = *(const uint32_t *)mxGetData(a); break;
    case mxINT64_CLASS:
      i = *(const int64_t *)mxGetData(a);
      v = (double)i;
      exact = 1;
      break;
    case mxUINT64_CLASS: {
      uint64_t u = *(const uint64_t *)mxGetData(a);
      i = u > (uint64_t)INT64_MAX ? INT64_MAX : (int64_t)u;
      v = (double)u;
      exact = 1;
      break;
    }
    default: fail("cncrot:badClass", "%s must be %s; got %s", label(pos, name), expect, described(a)); return 0;
  }
  if (exact) {
    if (i < INT32_MIN || i > INT32_MAX) fail(range_id, "%s must be %s; got %s", label(pos, name), expect, number_text(v));
    return (int32_t)i;
  }
  if (!(v == floor(v)) || isinf(v)) {
    if (isinf(v)) fail(range_id, "%s must be %s; got %s", label(pos, name), expect, number_text(v));
    fail("cncrot:badArgument", "%s must be %s; got %s", label(pos, name), expect, number_text(v));
  }
  if (v < -2147483648.0 || v > 2147483647.0) fail(range_id, "%s must be %s; got %s", label(pos, name), expect, number_text(v));
  return (int32_t)v;
}

/* An integer whose values the library judges (a selector, decimals, an axis number). */
static int32_t integer_arg(const mxArray *a, int pos, const char *name) {
  return integer_arg_as(a, pos, name, "an integer", "cncrot:badArgument");
}

/* ------------------------------------------------------------------------------------ */
/* Conventions: 'intrinsic' / 'extrinsic', axis sequences 'ZXY'                          */

/* Whether the library takes `v` as a flag (0 or 1), asked of the library itself. */
static int library_flag(int32_t v) {
  double z[3] = {0, 0, 0}, m[9];
  return cncrot_matrix_from_angles(v, 0, z, m) != CNCROT_STATUS_BAD_FLAG;
}

/* Lower-case ASCII of text, for names: at most cap - 1 characters (more: returns 0). */
static int keyword(const uint32_t *u, size_t n, char *out, size_t cap) {
  if (n >= cap) return 0;
  for (size_t k = 0; k < n; k++) {
    uint32_t c = u[k];
    if (c >= 0x80) return 0;
    out[k] = (char)(c >= 'A' && c <= 'Z' ? c + ('a' - 'A') : c);
  }
  out[n] = '\0';
  return 1;
}

#define TEXT_CAP 64

/* The convention flag: 'intrinsic' or 'i' (1, about the rotated axes) or 'extrinsic' or
 * 'e' (0, about the fixed axes), case-insensitive, as char or string; or 1, 0, true, false
 * of any class. */
static int32_t convention_arg(const mxArray *a, int pos, const char *name) {
  static const char *expect = "'intrinsic', 'extrinsic', 1 or 0";
  size_t n = 0;
  const mxChar *c = chars_of(a, pos, name, &n);
  if (c != NULL) {
    uint32_t u[TEXT_CAP];
    size_t count = code_points(c, n, u, TEXT_CAP);
    char word[16];
    if (keyword(u, count, word, sizeof word)) {
      /* 'i' and 'e' as the command line takes them (intrinsic:ZXY, e:XYZ). */
      if (strcmp(word, "intrinsic") == 0 || strcmp(word, "i") == 0) return 1;
      if (strcmp(word, "extrinsic") == 0 || strcmp(word, "e") == 0) return 0;
    }
    fail("cncrot:badFlag", "%s must be %s; got %s", label(pos, name), expect, quoted(u, count, count < TEXT_CAP ? count : TEXT_CAP));
  }
  int32_t v = integer_arg_as(a, pos, name, expect, "cncrot:badFlag");
  if (!library_flag(v)) fail("cncrot:badFlag", "%s must be %s; got %d", label(pos, name), expect, (int)v);
  return v;
}

/* A 0/1 switch of any numeric class or logical (CYCLE600's _SW_REC, _ROT_AD, ...). */
static int32_t switch_arg(const mxArray *a, int pos, const char *name) {
  static const char *expect = "0 or 1 (or false or true)";
  int32_t v = integer_arg_as(a, pos, name, expect, "cncrot:badFlag");
  if (!library_flag(v)) fail("cncrot:badFlag", "%s must be %s; got %d", label(pos, name), expect, (int)v);
  return v;
}

/* The letters of a code: 57 -> "XYZ", 49 -> "X0Z" (a code 0..63). */
static const char *sequence_letters(int32_t code) {
  static char buf[4];
  for (int k = 0; k < 3; k++) buf[k] = "0XYZ"[(code >> (2 * k)) & 3];
  buf[3] = '\0';
  return buf;
}

/* An axis sequence: its letters X, Y, Z (either case) in rotation order, '0' for a skipped
 * rotation, primes (' " ` and their Unicode forms) ignored -- 'ZXY', "ZX'Y''", 'x0z' --
 * as char or string; or the code a1 + 4*a2 + 16*a3 (X = 1, Y = 2, Z = 3, none = 0) of any
 * numeric class. The code is checked by the library (no axis repeated); `three` asks for
 * three rotations (a decomposition's sequence). */
static int32_t sequence_arg(const mxArray *a, int pos, const char *name, int three) {
  static const char *expect = "an axis sequence such as 'ZXY' or a code 0..63";
  size_t n = 0;
  const mxChar *c = chars_of(a, pos, name, &n);
  int32_t code = 0;
  const char *given;
  if (c != NULL) {
    uint32_t u[TEXT_CAP];
    size_t count = code_points(c, n, u, TEXT_CAP), slots = 0, stored = count < TEXT_CAP ? count : TEXT_CAP;
    int ok = count <= TEXT_CAP;
    for (size_t k = 0; ok && k < stored; k++) {
      uint32_t ch = u[k];
      int axis;
      if (ch == '\'' || ch == '"' || ch == '`' || ch == 0xB4 || ch == 0x2019 || ch == 0x201D || ch == 0x2032 || ch == 0x2033 || ch == 0x2034)
        continue;
      if (ch == 'x' || ch == 'X') axis = 1;
      else if (ch == 'y' || ch == 'Y') axis = 2;
      else if (ch == 'z' || ch == 'Z') axis = 3;
      else if (ch == '0') axis = 0;
      else {
        ok = 0;
        break;
      }
      if (slots < 3) code += axis << (2 * slots);
      slots++;
    }
    given = quoted(u, count, stored);
    if (!ok || slots != 3) fail("cncrot:badSequence", "%s must be %s; got %s", label(pos, name), expect, given);
  } else {
    code = integer_arg_as(a, pos, name, expect, "cncrot:badSequence");
    given = NULL;
  }
  double z[3] = {0, 0, 0}, m[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, angles[3];
  if (cncrot_matrix_from_angles(1, code, z, m) == CNCROT_STATUS_BAD_SEQUENCE) {
    if (given) fail("cncrot:badSequence", "%s must be %s; got %s (an axis repeats the one before it)", label(pos, name), expect, given);
    if (code < 0 || code > 63) fail("cncrot:badSequence", "%s must be %s; got %d", label(pos, name), expect, (int)code);
    fail("cncrot:badSequence", "%s must be %s; got %d ('%s': an axis repeats the one before it)", label(pos, name), expect,
         (int)code, sequence_letters(code));
  }
  double eye[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  if (three && cncrot_angles_from_matrix(1, code, eye, angles) == CNCROT_STATUS_INCOMPLETE_SEQUENCE) {
    if (given) fail("cncrot:incompleteSequence", "%s must be a sequence of three rotations such as 'ZXY' (no '0'); got %s", label(pos, name), given);
    fail("cncrot:incompleteSequence", "%s must be a sequence of three rotations such as 'ZXY' (no '0'); got %d ('%s')",
         label(pos, name), (int)code, sequence_letters(code));
  }
  return code;
}

/* ------------------------------------------------------------------------------------ */
/* Dialects, rules and forms by name                                                     */

typedef struct {
  const char *name;
  int32_t code;
} named_code;

/* The header's CNCROT_DIALECT_*, CNCROT_CHOOSE_*, CNCROT_FORM_*: lower case, no prefix. */
static const named_code DIALECTS[] = {
    {"sinumerik", CNCROT_DIALECT_SINUMERIK}, {"heidenhain", CNCROT_DIALECT_HEIDENHAIN}, {"fanuc", CNCROT_DIALECT_FANUC},
    {"syntec", CNCROT_DIALECT_SYNTEC},       {"twincat", CNCROT_DIALECT_TWINCAT},       {"haas", CNCROT_DIALECT_HAAS},
};
static const named_code RULES[] = {
    {"closest", CNCROT_CHOOSE_CLOSEST},
    {"minus", CNCROT_CHOOSE_MINUS},
    {"plus", CNCROT_CHOOSE_PLUS},
    {"inverse", CNCROT_CHOOSE_INVERSE},
    {"positive_turn", CNCROT_CHOOSE_POSITIVE_TURN},
    {"negative_turn", CNCROT_CHOOSE_NEGATIVE_TURN},
    {"master_first", CNCROT_CHOOSE_MASTER_FIRST},
};
static const named_code FORMS[] = {
    {"cycle800", CNCROT_FORM_CYCLE800},
    {"sinumerik_rot", CNCROT_FORM_SINUMERIK_ROT},
    {"sinumerik_rots", CNCROT_FORM_SINUMERIK_ROTS},
    {"plane_spatial", CNCROT_FORM_PLANE_SPATIAL},
    {"plane_euler", CNCROT_FORM_PLANE_EULER},
    {"plane_vector", CNCROT_FORM_PLANE_VECTOR},
    {"plane_points", CNCROT_FORM_PLANE_POINTS},
    {"g68_2", CNCROT_FORM_G68_2},
    {"g158", CNCROT_FORM_G158},
    {"twincat_rot", CNCROT_FORM_TWINCAT_ROT},
    {"g268", CNCROT_FORM_G268},
    {"g68_3", CNCROT_FORM_G68_3},
    {"plane_projected", CNCROT_FORM_PLANE_PROJECTED},
};
#define COUNT_OF(t) (sizeof(t) / sizeof((t)[0]))

/* "one of 'a', 'b', 'c' or a code 1..3" of a table (codes ascending in every table). */
static const char *choices(const named_code *t, size_t n, const char *what) {
  static char buf[400];
  int len = snprintf(buf, sizeof buf, "%s: one of ", what);
  for (size_t k = 0; k < n && len < (int)sizeof buf; k++)
    len += snprintf(buf + len, sizeof buf - len, "'%s'%s", t[k].name, k + 1 < n ? ", " : "");
  if (len < (int)sizeof buf) snprintf(buf + len, sizeof buf - len, ", or a code %d..%d", (int)t[0].code, (int)t[n - 1].code);
  return buf;
}

/* A name of a table (case-insensitive; for forms and rules ' ', '.' and '-' count as '_', so
 * that 'G68.2' and 'PLANE SPATIAL' are g68_2 and plane_spatial, 'positive turn' positive_turn)
 * or a code of any numeric class.
 * `known` says whether the library takes a code (NULL: the table's codes). */
static int32_t named_arg(const mxArray *a, int pos, const char *name, const named_code *t, size_t count, const char *what,
                         const char *id, int loose, int (*known)(int32_t)) {
  const char *expect = choices(t, count, what);
  size_t n = 0;
  const mxChar *c = chars_of(a, pos, name, &n);
  if (c != NULL) {
    uint32_t u[TEXT_CAP];
    size_t all = code_points(c, n, u, TEXT_CAP);
    char word[32];
    if (keyword(u, all, word, sizeof word)) {
      if (loose)
        for (char *p = word; *p; p++)
          if (*p == ' ' || *p == '.' || *p == '-') *p = '_';
      for (size_t k = 0; k < count; k++)
        if (strcmp(word, t[k].name) == 0) return t[k].code;
    }
    fail(id, "%s must be %s; got %s", label(pos, name), expect, quoted(u, all, all < TEXT_CAP ? all : TEXT_CAP));
  }
  int32_t v = integer_arg_as(a, pos, name, expect, id);
  int ok = 0;
  if (known) ok = known(v);
  else
    for (size_t k = 0; k < count; k++) ok |= t[k].code == v;
  if (!ok) fail(id, "%s must be %s; got %d", label(pos, name), expect, (int)v);
  return v;
}

/* Whether the library knows a dialect: a blank line of it is read (a new program). */
static int library_dialect(int32_t d) {
  cncrot_program p;
  memset(&p, 0, sizeof p);
  if (cncrot_program_init(&p, 0) < 0) return 1; /* cannot tell: the library judges later */
  return cncrot_program_line(&p, d, "", 0) != CNCROT_STATUS_BAD_ARGUMENT;
}

/* Whether the library knows a form. */
static int library_form(int32_t f) {
  size_t count = 0;
  return cncrot_form_word_count(f, &count) >= 0;
}

static int32_t dialect_arg(const mxArray *a, int pos, const char *name) {
  return named_arg(a, pos, name, DIALECTS, COUNT_OF(DIALECTS), "a dialect", "cncrot:badArgument", 0, library_dialect);
}

static int32_t rule_arg(const mxArray *a, int pos, const char *name) {
  return named_arg(a, pos, name, RULES, COUNT_OF(RULES), "a rule", "cncrot:badArgument", 1, NULL);
}

/* The reference axis argument (at `pos`) against its rule: an axis of the machine (1..count)
 * for the rules that name one, 0 for 'closest' and 'inverse' (what the library refuses as a
 * bad argument, said in the caller's terms). */
static void rule_ref_check(int32_t rule, int32_t ref, int count, int pos) {
  int sided = rule != CNCROT_CHOOSE_CLOSEST && rule != CNCROT_CHOOSE_INVERSE;
  if (sided && (ref < 1 || ref > count))
    fail("cncrot:badArgument", "%s must be an axis of the machine, 1..%d, for rule 'minus', 'plus', 'positive_turn', 'negative_turn' or 'master_first'; got %d",
         label(pos, "ref"), count, (int)ref);
  if (!sided && ref != 0)
    fail("cncrot:badArgument", "%s must be 0 (or left out) for rule 'closest' or 'inverse'; got %d", label(pos, "ref"), (int)ref);
}

static int32_t form_arg(const mxArray *a, int pos, const char *name) {
  return named_arg(a, pos, name, FORMS, COUNT_OF(FORMS), "a form", "cncrot:badArgument", 1, library_form);
}

/* The number of words of a form (the library's table). */
/* The writer's name of each form of FORMS, in its order. */
static const char *const FORM_TEXTS[] = {
    "CYCLE800",     "ROT", "ROTS", "PLANE SPATIAL", "PLANE EULER", "PLANE VECTOR",   "PLANE POINTS",
    "G68.2",        "G158", "ROT", "G268",          "G68.3",       "PLANE PROJECTED",
};

/* A writer's form name ('G68.2', "PLANE SPATIAL", 'G158 P10157'): text of at most 64
 * characters without NUL, as the library reads it (characters beyond ASCII become a byte it
 * refuses); or, as everywhere a form is taken, a form's name of cncrot_forms ('g68_2',
 * 'plane_spatial') or its code of any numeric class, written as the writer names it. */
static void form_name_arg(const mxArray *a, int pos, char out[65]) {
  size_t m = 0;
  const mxChar *c = chars_of(a, pos, "form", &m);
  if (c == NULL && (mxIsNumeric(a) || mxIsLogical(a))) {
    int32_t code = form_arg(a, pos, "form");
    for (size_t k = 0; k < COUNT_OF(FORMS); k++)
      if (FORMS[k].code == code) {
        snprintf(out, 65, "%s", FORM_TEXTS[k]);
        return;
      }
  }
  if (c == NULL)
    fail("cncrot:badClass", "%s must be text such as 'G68.2' or 'PLANE SPATIAL', or a form's code; got %s",
         label(pos, "form"), described(a));
  if (m > 0 && m < 32) {
    uint32_t u[32];
    char word[32];
    size_t all = code_points(c, m, u, 32);
    if (keyword(u, all, word, sizeof word)) {
      for (char *p = word; *p; p++)
        if (*p == ' ' || *p == '.' || *p == '-') *p = '_';
      for (size_t k = 0; k < COUNT_OF(FORMS); k++)
        if (strcmp(word, FORMS[k].name) == 0) {
          snprintf(out, 65, "%s", FORM_TEXTS[k]);
          return;
        }
    }
  }
  if (m > 64) fail("cncrot:badArgument", "%s is longer than 64 characters", label(pos, "form"));
  for (size_t k = 0; k < m; k++) {
    if (char_code(c[k]) == 0) fail("cncrot:badArgument", "%s contains a NUL character", label(pos, "form"));
    out[k] = ascii_byte(c[k]);
  }
  out[m] = '\0';
}

static size_t form_words(int32_t form, int pos) {
  size_t count = 0;
  int32_t s = cncrot_form_word_count(form, &count);
  if (s < 0) raise_status(s, label(pos, "form"), NULL, -1, 0);
  return count;
}

/* ------------------------------------------------------------------------------------ */
/* Arrays                                                                                */

/* N-by-cols real double (N >= 0; [] is accepted as 0-by-cols); returns N. */
static size_t rows_arg(const mxArray *a, int pos, const char *name, size_t cols) {
  (void)real_data(a, pos, name);
  if (mxGetNumberOfDimensions(a) == 2 && mxGetM(a) == 0 && (mxGetN(a) == cols || mxGetN(a) == 0)) return 0;
  if (mxGetNumberOfDimensions(a) != 2 || mxGetN(a) != cols) {
    const mwSize *d = mxGetDimensions(a);
    fail("cncrot:badSize", "%s must be N-by-%d; got %d-by-%d%s", label(pos, name), (int)cols, (int)d[0], (int)d[1],
         mxGetNumberOfDimensions(a) > 2 ? "-by-..." : "");
  }
  return mxGetM(a);
}

static size_t rows3_arg(const mxArray *a, int pos, const char *name) { return rows_arg(a, pos, name, 3); }

/* n-by-n or n-by-n-by-N real double (N >= 0; [] is accepted as none); returns N. */
static size_t squares_arg(const mxArray *a, int pos, const char *name, size_t n) {
  (void)real_data(a, pos, name);
  const mwSize *d = mxGetDimensions(a);
  mwSize nd = mxGetNumberOfDimensions(a);
  if (nd == 2 && d[0] == 0 && d[1] == 0) return 0;
  if (nd > 3 || (size_t)d[0] != n || (size_t)d[1] != n)
    fail("cncrot:badSize", "%s must be %d-by-%d or %d-by-%d-by-N; got %s", label(pos, name), (int)n, (int)n, (int)n, (int)n,
         described(a));
  return nd == 3 ? d[2] : 1;
}

static size_t matrices_arg(const mxArray *a, int pos, const char *name) { return squares_arg(a, pos, name, 3); }

/* One 4-by-4 frame. */
static void frame_arg(const mxArray *a, int pos, const char *name, double row_major[16]);

/* A vector of 3 elements (any orientation). */
static void point_arg(const mxArray *a, int pos, const char *name, double p[3]) {
  const double *d = real_data(a, pos, name);
  if (mxGetNumberOfElements(a) != 3) fail("cncrot:badSize", "%s must have 3 elements; got %s", label(pos, name), described(a));
  memcpy(p, d, 3 * sizeof(double));
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

static void frame_arg(const mxArray *a, int pos, const char *name, double row_major[16]) {
  (void)real_data(a, pos, name);
  if (mxGetNumberOfDimensions(a) != 2 || mxGetM(a) != 4 || mxGetN(a) != 4)
    fail("cncrot:badSize", "%s must be 4-by-4; got %s", label(pos, name), described(a));
  frame_to_row_major(real_data(a, pos, name), row_major);
}

/* A number that must be finite, named in the error when it is not. */
static double finite_arg(double v, int pos, const char *name) {
  if (!(v - v == 0)) fail("cncrot:notFinite", "%s must be a finite number; got %s", label(pos, name), number_text(v));
  return v;
}

/* The previous machine axes of the five-axis transformation: 6 finite elements (X Y Z and
 * 3 rotary axes). */
static void previous_arg(const mxArray *a, int pos, double prev[6]) {
  const double *q = real_data(a, pos, "previous");
  if (mxGetNumberOfElements(a) != 6)
    fail("cncrot:badSize", "%s must have 6 elements (X Y Z and 3 rotary axes); got %s", label(pos, "previous"),
         described(a));
  for (int k = 0; k < 6; k++)
    if (!(q[k] - q[k] == 0))
      fail("cncrot:notFinite", "%s must be finite; element %d is %s", label(pos, "previous"), k + 1, number_text(q[k]));
  memcpy(prev, q, 6 * sizeof(double));
}

/* A machine: SINUMERIK swivel-data text (data set 1), or a K-by-12 matrix, one row per
 * axis outermost first: [work_side vx vy vz px py pz min max offset hirth_offset hirth_step].
 * Errors are raised here, after the library has returned. */
static void machine_arg(const mxArray *a, int pos, cncrot_machine *m) {
  memset(m, 0, sizeof *m);
  size_t n = 0;
  const mxChar *c = chars_of(a, pos, "machine", &n);
  if (c != NULL) {
    char *t = (char *)mxMalloc(n + 1);
    for (size_t k = 0; k < n; k++) t[k] = char_code(c[k]) == 0 ? (char)0x80 : ascii_byte(c[k]);
    t[n] = '\0';
    int32_t s = cncrot_machine_from_carr(m, t, n, 1), line = 0;
    if (s < 0) cncrot_machine_carr_error_line(t, n, 1, &line);
    mxFree(t);
    if (s < 0) {
      char where[160];
      snprintf(where, sizeof where, "%s, swivel data line %d", label(pos, "machine"), (int)line);
      raise_at(s, where, NULL, -1, 0);
    }
    return;
  }
  if (!mxIsDouble(a))
    fail("cncrot:badClass", "%s must be swivel-data text or a K-by-12 double matrix; got %s", label(pos, "machine"), described(a));
  size_t k = rows_arg(a, pos, "machine", 12);
  if (k > 3) fail("cncrot:badSize", "%s has at most 3 axes (rows); got %d", label(pos, "machine"), (int)k);
  const double *d = real_data(a, pos, "machine");
  for (size_t r = 0; r < k; r++) {
    double row[12];
    for (int col = 0; col < 12; col++) row[col] = d[r + k * col];
    int32_t side = row[0] == 0 ? 0 : row[0] == 1 ? 1 : 2;
    int32_t s = cncrot_machine_add_axis(m, side, row + 1, row + 4, row[7], row[8]);
    if (s < 0) raise_at(s, label(pos, "machine"), "row", (long)r, k);
    m->axes[r].offset_deg = row[9];
    m->axes[r].hirth_offset_deg = row[10];
    m->axes[r].hirth_step_deg = row[11];
  }
  /* Sealed once here, so that a whole path's calls check the seal instead of every field. A
   * description that is not a machine stays as it is: the call that reads it raises the error
   * (a sealed description computes exactly as the unsealed one). */
  (void)cncrot_machine_seal(m);
}

/* Statuses of a batch call are preset to this, which no status has: a row still holding it
 * was not computed (the call was refused before the rows). */
#define NOT_COMPUTED INT32_MIN

/* After a batch call that returned `r`: raises the first failing row's error (naming the
 * row when there are several), or the refusal's. */
static void raise_batch(int32_t r, const int32_t *st, size_t n, const char *where, const char *unit) {
  size_t k;
  if (r >= 0) return;
  for (k = 0; k < n; k++)
    if (st[k] < 0 && st[k] != NOT_COMPUTED) raise_status(st[k], where, unit, (long)k, n);
  raise_status(r, NULL, NULL, -1, 0);
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

#endif
