% CNCROT_PROGRAM_LINES  What program lines do to the active frame, as the controller does.
%   [F, state, frames] = cncrot_program_lines(dialect, lines)
%   [F, state, frames] = cncrot_program_lines(dialect, lines, state)
%   [F, state, frames, remarks] = cncrot_program_lines(...)
%   [...] = cncrot_program_lines(dialect, lines, state, machine)
%   dialect: 'sinumerik', 'heidenhain', 'fanuc', 'syntec', 'twincat' or 'haas' (any case,
%   char or string), or its code (cncrot_dialects, of any numeric class); lines: one block
%   (a char row or a string) or several (a cell array of them, or a string array), applied
%   in order. F is the 4-by-4 active frame after the last line (p_old = F * [p_new; 1]),
%   state the program's modal state to pass to the next call (start from [], or from
%   struct('options', 1) to read SINUMERIK frame angles in Euler mode, 2 to read
%   Heidenhain's CYCL DEF 19 angles as rotary-axis positions, 3 both; options of any
%   numeric class), frames the frame after each line (4-by-4-by-N). The state keeps the
%   datum shift apart from the tilt (state.shift: CYCL DEF 7, TRANS DATUM, G52) and the
%   tilt's own choice words (state.choice 1 minus, 2 plus for SEQ-/SEQ+ and _DIR, 4 / 5
%   positive / negative turn for G53.1 P1 / P2, with state.reference_axis;
%   cncrot_program_axes follows them) and how the program moves the
%   machine to the tilt (state.positioning 0 stay, 1 turn for TURN, G53.1, G253, a
%   CYCLE800 with _DIR -1 or +1 (_DIR 0: stay), 2 move for MOVE, G53.6; with no tilt active, 1 or 2 turn the axes to the untilted plane:
%   PLANE RESET TURN, a zero tilt with TURN; state.retract 0 none, 1 MB MAX / _FR 4, 2 MB n / _FR 5 by
%   state.retract_mm, 3 _FR 1 along machine Z, 4 _FR 2 along Z then X Y; state.feed 0 FMAX,
%   1 F n at state.feed_mm_min, 2 F AUTO) and the working plane (state.plane 0 G17, 1 G18,
%   2 G19: the plane of ROT RPL= and G68 X Y R) and Heidenhain's TABLE ROT (state.table_rot 1:
%   cncrot_program_axes turns a free rotary table to the plane; 0 for COORD ROT or none),
%   and whether the active tilt was added to the one before (state.relative 1 after PLANE
%   RELATIV, G68.4, a CYCLE800 with _ST 1, AROT, G158 P01...: cncrot_program_translate
%   writes the target's incremental form, so that a loop repeating the block adds as often).
%   A direct mode (PLANE AXIAL, G158 mode 2, a CYCLE800 with _MODE 192) keeps the rotary-axis positions (state.angles; state.active 2 by letter A,
%   B, C, 3 by the machine's axes 1, 2, 3; state.direct_given which were given): its frame
%   follows from the machine's kinematics, NaN without one; with machine (as in
%   cncrot_machine_forward: a swivel-data text or axis rows) it is the rotation the machine
%   reaches there, about the block's origin. The state carries a
%   seal: a state whose fields were changed is refused (cncrot:badState). Every block of a
%   program is read: remarks (N-by-1 cell) says for each line 'applied' (a command that
%   concerns the frame), 'passed' (motion, tool, M words, comments, program structure: the
%   state unchanged) or 'not followed' (a work offset, preset, datum shift or table,
%   mirroring, scaling: the state unchanged, and it may no longer be the control's).
%   A line the controller could not execute raises the status's error (cncrot:unknownWord,
%   cncrot:notANumber for a variable, cncrot:missingWord, cncrot:parse, cncrot:lineTooLong,
%   or the error of the command's mathematics) whose message names the line, the column
%   of the first offending character and what was wrong there: the word the reader wanted,
%   a cycle parameter's allowed values, or the word it could not use
%   ("cncrot_program_lines: argument 2 (lines), line 1, column 27 (missing: SPC): ...").
%
%   Example (the TwinCAT manual: ROT Z30 then AROT Z15 is 45 degrees about Z):
%     F = cncrot_program_lines('twincat', {'N65 ROT Z30', 'N90 AROT Z15'})
%     F = cncrot_program_lines(cncrot_dialects().TWINCAT, {'N65 ROT Z30', 'N90 AROT Z15'})   % the same
%     F = cncrot_program_lines('heidenhain', '5 PLANE SPATIAL SPA+27 SPB+0 SPC+45 TURN FMAX')
%     [F, ~, ~, r] = cncrot_program_lines('fanuc', {'N10 G54', 'N20 G68.2 J30', 'N30 G1 X10'})
%     % r = {'not followed'; 'applied'; 'passed'}
%     hd = [0 0 0 1 0 0 0 0 0 0 0 0; 0 0 1 0 0 0 150 -100 100 0 0 0];   % C carrying B
%     F = cncrot_program_lines('heidenhain', 'PLANE AXIAL B+30 C+45', [], hd)
%
%   See also CNCROT_PROGRAM_WRITE, CNCROT_PROGRAM_TRANSLATE, CNCROT_DIALECTS, CNCROT_FORM_FRAME.
