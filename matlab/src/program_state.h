/* The program state as a MATLAB struct (rotation, origin, angles, shift, active, dialect,
 * options, choice, reference_axis, positioning, direct_given, retract, retract_mm,
 * feed_mm_min, feed, plane, table_rot, relative, seal) and back, and the reading of program lines: shared by
 * cncrot_program_lines, cncrot_program_translate and cncrot_program_axes. */
#ifndef CNCROT_PROGRAM_STATE_H
#define CNCROT_PROGRAM_STATE_H
#include "gateway.h"

static const char *FIELDS[] = {"rotation", "origin", "angles", "shift", "active", "dialect",
                               "options", "choice", "reference_axis", "positioning", "direct_given",
                               "retract", "retract_mm", "feed_mm_min", "feed", "plane", "table_rot", "relative", "seal"};

/* A field of the state struct as n doubles (absent: zeros; wrong size: an error). */
static void field(const mxArray *s, int arg, const char *name, double *out, size_t n) {
  memset(out, 0, n * sizeof *out);
  const mxArray *f = mxGetField(s, 0, name);
  if (!f) return;
  if (!mxIsDouble(f) || mxIsComplex(f) || mxIsSparse(f) || mxGetNumberOfElements(f) != n)
    fail("cncrot:badState", "%s: field %s must be %d real doubles", label(arg, "state"), name, (int)n);
  const double *d = real_data(f, arg, "state");
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
static void from_struct(const mxArray *s, int arg, cncrot_program *p) {
  memset(p, 0, sizeof *p);
  if (mxIsEmpty(s) && !mxIsStruct(s)) return;
  if (!mxIsStruct(s) || mxGetNumberOfElements(s) != 1)
    fail("cncrot:badClass", "%s must be a 1-by-1 struct from cncrot_program_lines, or []; got %s", label(arg, "state"), described(s));
  /* A field of another name is a misspelling (struct('Options', 1)): refused, as inputParser
     refuses an unknown name, rather than left out in silence. */
  for (int k = 0; k < mxGetNumberOfFields(s); k++) {
    const char *name = mxGetFieldNameByNumber(s, k);
    int known = 0;
    for (size_t j = 0; j < COUNT_OF(FIELDS); j++) known |= strcmp(name, FIELDS[j]) == 0;
    if (!known)
      fail("cncrot:badState", "%s: '%s' is not a field of a program state (a new program takes only 'options')",
           label(arg, "state"), name);
  }
  double r[9], v[3];
  field(s, arg, "rotation", r, 9);
  to_row_major(r, p->rotation);
  field(s, arg, "origin", p->origin, 3);
  field(s, arg, "angles", p->angles, 3);
  field(s, arg, "shift", p->shift, 3);
  field(s, arg, "choice", v, 1);
  p->choice = as_int(v[0]);
  field(s, arg, "reference_axis", v, 1);
  p->reference_axis = as_int(v[0]);
  field(s, arg, "positioning", v, 1);
  p->positioning = as_int(v[0]);
  field(s, arg, "active", v, 1);
  p->active = as_int(v[0]);
  field(s, arg, "dialect", v, 1);
  p->dialect = as_int(v[0]);
  /* The one field a user sets: any numeric class or logical (struct('options', int32(1))). */
  const mxArray *o = mxGetField(s, 0, "options");
  if (o && !mxIsDouble(o) && (mxIsNumeric(o) || mxIsLogical(o)) && !mxIsComplex(o) && !mxIsSparse(o) && mxGetNumberOfElements(o) == 1)
    v[0] = mxGetScalar(o);
  else field(s, arg, "options", v, 1);
  p->options = as_u32(v[0]);
  field(s, arg, "direct_given", v, 1);
  p->direct_given = as_u32(v[0]);
  field(s, arg, "retract", v, 1);
  p->retract = as_int(v[0]);
  field(s, arg, "retract_mm", &p->retract_mm, 1);
  field(s, arg, "feed_mm_min", &p->feed_mm_min, 1);
  field(s, arg, "feed", v, 1);
  p->feed = as_int(v[0]);
  field(s, arg, "plane", v, 1);
  p->plane = as_int(v[0]);
  field(s, arg, "table_rot", v, 1);
  p->table_rot = as_u32(v[0]);
  field(s, arg, "relative", v, 1);
  p->relative = as_u32(v[0]);
  if (mxGetField(s, 0, "seal")) {
    field(s, arg, "seal", v, 1);
    p->reserved = as_u32(v[0]);
    return;
  }
  cncrot_program fresh;
  memset(&fresh, 0, sizeof fresh);
  fresh.options = p->options;
  if (memcmp(&fresh, p, sizeof fresh) == 0 && cncrot_program_init(p, fresh.options) < 0)
    fail("cncrot:badState", "%s: options %u is not a combination of cncrot program options", label(arg, "state"), (unsigned)fresh.options);
}

static mxArray *to_struct(const cncrot_program *p) {
  mxArray *s = mxCreateStructMatrix(1, 1, (int)COUNT_OF(FIELDS), FIELDS);
  mxArray *r = mxCreateDoubleMatrix(3, 3, mxREAL);
  to_col_major(p->rotation, mxGetDoubles(r));
  mxSetField(s, 0, "rotation", r);
  mxArray *o = mxCreateDoubleMatrix(1, 3, mxREAL), *a = mxCreateDoubleMatrix(1, 3, mxREAL);
  memcpy(mxGetDoubles(o), p->origin, sizeof p->origin);
  memcpy(mxGetDoubles(a), p->angles, sizeof p->angles);
  mxSetField(s, 0, "origin", o);
  mxSetField(s, 0, "angles", a);
  mxArray *sh = mxCreateDoubleMatrix(1, 3, mxREAL);
  memcpy(mxGetDoubles(sh), p->shift, sizeof p->shift);
  mxSetField(s, 0, "shift", sh);
  mxSetField(s, 0, "choice", mxCreateDoubleScalar(p->choice));
  mxSetField(s, 0, "reference_axis", mxCreateDoubleScalar(p->reference_axis));
  mxSetField(s, 0, "positioning", mxCreateDoubleScalar(p->positioning));
  mxSetField(s, 0, "active", mxCreateDoubleScalar(p->active));
  mxSetField(s, 0, "dialect", mxCreateDoubleScalar(p->dialect));
  mxSetField(s, 0, "options", mxCreateDoubleScalar(p->options));
  mxSetField(s, 0, "direct_given", mxCreateDoubleScalar(p->direct_given));
  mxSetField(s, 0, "retract", mxCreateDoubleScalar(p->retract));
  mxSetField(s, 0, "retract_mm", mxCreateDoubleScalar(p->retract_mm));
  mxSetField(s, 0, "feed_mm_min", mxCreateDoubleScalar(p->feed_mm_min));
  mxSetField(s, 0, "feed", mxCreateDoubleScalar(p->feed));
  mxSetField(s, 0, "plane", mxCreateDoubleScalar(p->plane));
  mxSetField(s, 0, "table_rot", mxCreateDoubleScalar(p->table_rot));
  mxSetField(s, 0, "relative", mxCreateDoubleScalar(p->relative));
  mxSetField(s, 0, "seal", mxCreateDoubleScalar(p->reserved));
  return s;
}

/* The active frame of p: on machine m when one is given (a direct mode's frame follows from
 * it), else the state's own, NaN for a direct mode (PLANE AXIAL, CYCLE800 direct, G158 mode
 * 2), whose frame needs the machine. Returns the library's status otherwise. */
static int32_t frame_of(const cncrot_program *p, const cncrot_machine *m, double f[16]) {
  int32_t s = m ? cncrot_program_frame_on(p, m, f) : cncrot_program_frame(p, f);
  if (s == CNCROT_STATUS_NOT_AVAILABLE && m == NULL) {
    for (int k = 0; k < 16; k++) f[k] = NAN;
    return CNCROT_STATUS_OK;
  }
  return s;
}

/* A char row of `len` characters from c (stride `step`) as an mxArray. */
static mxArray *char_row(const mxChar *c, size_t len, size_t step) {
  mwSize dims[2] = {1, len};
  mxArray *row = mxCreateCharArray(2, dims);
  mxChar *out = mxGetChars(row);
  for (size_t k = 0; k < len; k++) out[k] = c[k * step];
  return row;
}

/* Program lines as given: a cell array of char rows or strings, a string array (its
 * elements as a cell array of char, by MATLAB's cellstr), a char matrix (a line per row,
 * trailing blanks dropped, as cellstr takes it), or one text: a char row or string scalar
 * holding line breaks (what fileread returns) is split at them, a last empty line after a
 * final break dropped (a CR before a break is the line's, and read as its end). */
static const mxArray *lines_arg(const mxArray *lines, int pos) {
  if (mxIsClass(lines, "string") && mxGetNumberOfElements(lines) != 1) {
    mxArray *cells = NULL, *in = (mxArray *)lines;
    if (mexCallMATLABWithTrap(1, &cells, 1, &in, "cellstr") != NULL || cells == NULL)
      fail("cncrot:badClass", "%s: the strings could not be read (a missing string?)", label(pos, "lines"));
    return cells;
  }
  const mxArray *text = lines;
  if (mxIsClass(lines, "string")) {
    mxArray *c = NULL, *in = (mxArray *)lines;
    if (mexCallMATLABWithTrap(1, &c, 1, &in, "char") != NULL || c == NULL || !mxIsChar(c))
      fail("cncrot:badClass", "%s: the string could not be read (a missing string?)", label(pos, "lines"));
    text = c;
  }
  if (!mxIsChar(text) || mxGetNumberOfDimensions(text) != 2) return lines;
  size_t m = mxGetM(text), n = mxGetN(text);
  const mxChar *c = mxGetChars(text);
  if (m > 1) {
    mxArray *cells = mxCreateCellMatrix(m, 1);
    for (size_t r = 0; r < m; r++) {
      size_t len = n;
      while (len > 0 && char_code(c[r + (len - 1) * m]) == ' ') len--;
      mxSetCell(cells, r, char_row(c + r, len, m));
    }
    return cells;
  }
  size_t breaks = 0;
  for (size_t k = 0; k < n; k++) breaks += char_code(c[k]) == '\n';
  if (breaks == 0) return lines;
  size_t count = breaks + (char_code(c[n - 1]) == '\n' ? 0 : 1);
  mxArray *cells = mxCreateCellMatrix(count, 1);
  size_t start = 0, r = 0;
  for (size_t k = 0; k <= n && r < count; k++) {
    if (k == n || char_code(c[k]) == '\n') {
      mxSetCell(cells, r++, char_row(c + start, k - start, 1));
      start = k + 1;
    }
  }
  return cells;
}

/* One line of text as bytes (characters beyond ASCII become a byte every dialect refuses):
 * a char row vector or a string scalar. */
static size_t line_bytes(const mxArray *a, int pos, char *out, size_t cap) {
  size_t n = 0;
  const mxChar *c = chars_of(a, pos, "lines", &n);
  if (c == NULL)
    fail("cncrot:badClass", "%s must be text (char, a string, or a cell array of them); got %s", label(pos, "lines"),
         described(a));
  size_t k;
  /* Longer lines than any dialect reads arrive cut to cap bytes: the library refuses them. */
  for (k = 0; k < n && k < cap; k++) out[k] = ascii_byte(c[k]);
  return k;
}

/* Raises the refusal `s` of line k (of n) of argument `pos`, read on state p: the line, the
 * column of the first offending character and what was wrong there (the word the reader
 * wanted, a cycle parameter's allowed values, or the word it could not use). */
static void raise_line(int32_t s, const cncrot_program *p, int32_t dialect, const char *buf, size_t len, int pos,
                       size_t k, size_t n) {
  char what[CNCROT_PROGRAM_EXPECTED_SIZE];
  size_t column = 0;
  cncrot_program_column(p, dialect, buf, len, &column);
  cncrot_program_expected(p, dialect, buf, len, what, sizeof what);
  char where[96 + CNCROT_PROGRAM_EXPECTED_SIZE + 48];
  if (column > 0) {
    int at = snprintf(where, sizeof where, "%s, line %d, column %d", label(pos, "lines"), (int)(k + 1), (int)column);
    if (what[0] && at > 0 && (size_t)at < sizeof where) {
      snprintf(where + at, sizeof where - (size_t)at, " (%s%s)", s == CNCROT_STATUS_MISSING_WORD ? "missing: " : "",
               what);
    } else if (column <= len && at > 0 && (size_t)at < sizeof where) {
      size_t end = column - 1;
      while (end < len && end < column - 1 + 24 && buf[end] != ' ' && buf[end] != '\t') end++;
      snprintf(where + at, sizeof where - (size_t)at, " ('%.*s')", (int)(end - (column - 1)), buf + column - 1);
    }
    raise_at(s, where, NULL, -1, 0);
  }
  raise_at(s, label(pos, "lines"), "line", (long)k, n);
}

#endif
