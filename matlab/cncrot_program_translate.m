% CNCROT_PROGRAM_TRANSLATE  A part program in another controller's language, block by block.
%   text = cncrot_program_translate(dialect, lines, to, form)
%   text = cncrot_program_translate(dialect, lines, to, form, decimals)
%   [text, remarks, state] = cncrot_program_translate(...)
%   dialect, to: 'sinumerik', 'heidenhain', 'fanuc', 'syntec', 'twincat' or 'haas' (any
%   case, char or string), or the code (cncrot_dialects); lines: the program's blocks (a
%   cell array of char or strings, a string array, or one block); form: the tilt command
%   to write in (the forms of cncrot_program_write: 'PLANE SPATIAL', 'G68.2', 'CYCLE800',
%   ...); decimals: 0..17, or negative (the default) for the shortest numbers that read
%   back exactly. text (N-by-1 cell of char) holds for each block of the program:
%   - a block that concerns the frame: the blocks that program the same change in the
%     target language, separated by newline characters (char(10)), or '' when nothing
%     changes there. A datum shift is written with the target's own command (Heidenhain
%     CYCL DEF 7, G52, SINUMERIK TRANS), a tilt's origin as a datum shift where the form
%     has no origin words (PLANE), an active tilt cancelled before a new shift, cancels as
%     cancels (G69, PLANE RESET STAY, CYCLE800()) -- into another dialect also when nothing
%     was active (the safety cancel a program opens with), as a datum shift set to the
%     value it had is written again --, the tilt's choice words where the
%     block has them (SEQ+/SEQ- <-> CYCLE800 _DIR +1/-1) and how the machine moves to the
%     plane (TURN/MOVE/STAY <-> G53.1/G53.6, G253). A block that adds to the tilt (PLANE
%     RELATIV, G68.4, CYCLE800 with _ST 1, AROT, G158 P01...) is written as the target's
%     increment (PLANE RELATIV, G68.4, _ST 1, AROT, G158 P01...), so that a loop repeating
%     it adds as often (the plane it reaches where the target has none: Haas). A command spread over lines is
%     written once, at its last line ('' for the others): cycle 7's axis lines as one
%     G52, a G68.2 and its G53.1 as one PLANE ... TURN. The
%     block's other words (what an ISO-style post writes beside a tilt or a cancel:
%     'G91 G28 Z0.' of 'G91 G28 Z0. G69', 'N40 G1 F300.' of 'N40 G1 G68.2 ... F300.')
%     come first, as they stand, on a line of their own;
%   - any other block: the block as it stands (remarks says which). The blocks are read in
%     the order given: a Heidenhain CALL LBL is passed over, not followed through its
%     label, and a cancel beside a block not followed (G69 G55) stays in it as it stands
%     (the command line's 'cncrot program --to' follows the call, writes the cancel and
%     keeps a tilt block's number and comment, reads parameters set once to a number,
%     and names a turn or retraction the target has no word for).
%   remarks (N-by-1 cell): 'applied', 'passed' or 'not followed' as cncrot_program_lines
%   says; a 'not followed' block changes the frame in a way the library does not follow
%   and is not translated. state: the source program's state after the last block.
%   A block the source controller could not execute raises its error, as in
%   cncrot_program_lines; a change the target form cannot write raises its status's error
%   naming the line (cncrot:notAvailable for rotary-axis positions into a dialect that
%   states planes). Into SINUMERIK 'ROT', which has no origin words, a tilt with an origin
%   is 'TRANS X=… Y=… Z=…' and the rotation 'AROT' about it.
%
%   Example (a hyperMILL-style Heidenhain program for a Fanuc-style control):
%     prog = {'CYCL DEF 7.0 DATUM SHIFT', 'CYCL DEF 7.1 X+10', ...
%             'PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX SEQ-', 'L Z+100 FMAX', 'PLANE RESET STAY'};
%     text = cncrot_program_translate('heidenhain', prog, 'fanuc', 'G68.2', 4)
%     % {''; 'G52 X10. Y0. Z0.'; sprintf('G68.2 X0. Y0. Z0. I90. J30. K-90.\nG53.1'); 'L Z+100 FMAX'; 'G69'}
%
%   See also CNCROT_PROGRAM_LINES, CNCROT_PROGRAM_WRITE, CNCROT_DIALECTS.
