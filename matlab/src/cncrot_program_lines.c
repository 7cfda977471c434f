/* [F, state, frames, remarks] = cncrot_program_lines(dialect, lines, state): see
 * cncrot_program_lines.m. */
#include "gateway.h"

static const char *FIELDS[] = {"rotation", "origin", "angles", "active", "dialect", "options", "seal"};

/* A field of the state struct as n doubles (absent: zeros; wrong size: an error). */
static void field(const mxArray *s, const char *name, double *out, size_t n) {
  memset(out, 0, n * sizeof *out);
  const mxArray *f = mxGetField(s, 0, name);
  if (!f) return;
  if (!mxIsDouble(f) || mxIsComplex(f) || mxIsSparse(f) || mxGetNumberOfElements(f) != n)
    fail("cncrot:badState", "%s: field %s must be %d real doubles", label(3, "state"), name, (int)n);
  const double *d = real_data(f, 3, "state");
  memcpy(out, d, n * sizeof *out);
}

static int32_t as_int(double v) { return v >= -2147483648.0 && v <= 2147483647.0 ? (int32_t)v : INT32_MIN; }

/* A uint32 field given as a double (anything else: a value the library refuses). */
static uint32_t as_u32(double v) {
  return v >= 0 && v <= 4294967295.0 && v == (double)(uint32_t)v ? (uint32_t)v : 0xFFFFFFFFu;
}

/* The state struct as the library's; values the library did not write are refused by it
 * (cncrot:badState), after the call. A struct without a seal is a new program: only its
 * options may be set (struct('options', 1)), and cncrot_program_init seals it. */
static void from_struct(const mxArray *s, cncrot_program *p) {
  memset(p, 0, sizeof *p);
  if (mxIsEmpty(s) && !mxIsStruct(s)) return;
  if (!mxIsStruct(s) || mxGetNumberOfElements(s) != 1)
    fail("cncrot:badClass", "%s must be a 1-by-1 struct from cncrot_program_lines, or []; got %s", label(3, "state"), described(s));
  double r[9], v[3];
  field(s, "rotation", r, 9);
  to_row_major(r, p->rotation);
  field(s, "origin", p->origin, 3);
  field(s, "angles", p->angles, 3);
  field(s, "active", v, 1);
  p->active = as_int(v[0]);
  field(s, "dialect", v, 1);
  p->dialect = as_int(v[0]);
  /* The one field a user sets: any numeric class or logical (struct('options', int32(1))). */
  const mxArray *o = mxGetField(s, 0, "options");
  if (o && !mxIsDouble(o) && (mxIsNumeric(o) || mxIsLogical(o)) && !mxIsComplex(o) && !mxIsSparse(o) && mxGetNumberOfElements(o) == 1)
    v[0] = mxGetScalar(o);
  else field(s, "options", v, 1);
  p->options = as_u32(v[0]);
  if (mxGetField(s, 0, "seal")) {
    field(s, "seal", v, 1);
    p->reserved = as_u32(v[0]);
    return;
  }
  cncrot_program fresh;
  memset(&fresh, 0, sizeof fresh);
  fresh.options = p->options;
  if (memcmp(&fresh, p, sizeof fresh) == 0 && cncrot_program_init(p, fresh.options) < 0)
    fail("cncrot:badState", "%s: options %u is not a combination of cncrot program options", label(3, "state"), (unsigned)fresh.options);
}

static mxArray *to_struct(const cncrot_program *p) {
  mxArray *s = mxCreateStructMatrix(1, 1, 7, FIELDS);
  mxArray *r = mxCreateDoubleMatrix(3, 3, mxREAL);
  to_col_major(p->rotation, mxGetDoubles(r));
  mxSetField(s, 0, "rotation", r);
  mxArray *o = mxCreateDoubleMatrix(1, 3, mxREAL), *a = mxCreateDoubleMatrix(1, 3, mxREAL);
  memcpy(mxGetDoubles(o), p->origin, sizeof p->origin);
  memcpy(mxGetDoubles(a), p->angles, sizeof p->angles);
  mxSetField(s, 0, "origin", o);
  mxSetField(s, 0, "angles", a);
  mxSetField(s, 0, "active", mxCreateDoubleScalar(p->active));
  mxSetField(s, 0, "dialect", mxCreateDoubleScalar(p->dialect));
  mxSetField(s, 0, "options", mxCreateDoubleScalar(p->options));
  mxSetField(s, 0, "seal", mxCreateDoubleScalar(p->reserved));
  return s;
}

/* One line of text as bytes (characters beyond ASCII become a byte every dialect refuses):
 * a char row vector or a string scalar. */
static size_t line_bytes(const mxArray *a, char *out, size_t cap) {
  size_t n = 0;
  const mxChar *c = chars_of(a, 2, "lines", &n);
  if (c == NULL)
    fail("cncrot:badClass", "%s must be text (char, a string, or a cell array of them); got %s", label(2, "lines"), described(a));
  size_t k;
  /* Longer lines than any dialect reads arrive cut to cap bytes: the library refuses them. */
  for (k = 0; k < n && k < cap; k++) out[k] = ascii_byte(c[k]);
  return k;
}

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 2, 3, nlhs, 4);
  int32_t dialect = dialect_arg(prhs[0], 1, "dialect");
  cncrot_program p;
  if (nrhs == 3) from_struct(prhs[2], &p);
  else memset(&p, 0, sizeof p);
  const mxArray *lines = prhs[1];
  if (mxIsClass(lines, "string") && mxGetNumberOfElements(lines) != 1) {
    /* A string array: its elements as a cell array of char, by MATLAB's cellstr. */
    mxArray *cells = NULL, *in = (mxArray *)lines;
    if (mexCallMATLABWithTrap(1, &cells, 1, &in, "cellstr") != NULL || cells == NULL)
      fail("cncrot:badClass", "%s: the strings could not be read (a missing string?)", label(2, "lines"));
    lines = cells;
  }
  int cell = mxIsCell(lines);
  size_t n = cell ? mxGetNumberOfElements(lines) : 1;
  mxArray *frames = mxCreateNumericArray(3, (mwSize[]){4, 4, n}, mxDOUBLE_CLASS, mxREAL);
  /* What each block did: 'applied', 'passed' (not about the frame), 'not followed'. */
  mxArray *remarks = mxCreateCellMatrix(n, 1);
  double *fr = mxGetDoubles(frames);
  double f[16];
  /* The state's own check, also for no lines. */
  int32_t s = cncrot_program_frame(&p, f);
  if (s < 0) {
    mxDestroyArray(frames);
    raise_at(s, label(3, "state"), NULL, -1, 0);
  }
  for (size_t k = 0; k < n; k++) {
    const mxArray *a = cell ? mxGetCell(lines, k) : lines;
    if (!a) a = mxCreateString("");
    char buf[CNCROT_PROGRAM_LINE_MAX + 3];
    size_t len = line_bytes(a, buf, sizeof buf);
    size_t column = 0;
    s = cncrot_program_line(&p, dialect, buf, len);
    if (s < 0) {
      cncrot_program_column(&p, dialect, buf, len, &column);
      mxDestroyArray(frames);
      mxDestroyArray(remarks);
      char where[96];
      if (column > 0) {
        snprintf(where, sizeof where, "%s, line %d, column %d", label(2, "lines"), (int)(k + 1), (int)column);
        raise_at(s, where, NULL, -1, 0);
      }
      raise_at(s, label(2, "lines"), "line", (long)k, n);
    }
    mxSetCell(remarks, k,
              mxCreateString(s == CNCROT_STATUS_PASSED         ? "passed"
                             : s == CNCROT_STATUS_NOT_FOLLOWED ? "not followed"
                                                               : "applied"));
    cncrot_program_frame(&p, f);
    frame_to_col_major(f, fr + 16 * k);
  }
  mxArray *F = mxCreateDoubleMatrix(4, 4, mxREAL);
  frame_to_col_major(f, mxGetDoubles(F));
  plhs[0] = F;
  if (nlhs > 1) plhs[1] = to_struct(&p);
  if (nlhs > 2) plhs[2] = frames; else mxDestroyArray(frames);
  if (nlhs > 3) plhs[3] = remarks; else mxDestroyArray(remarks);
}
