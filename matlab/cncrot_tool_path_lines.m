% CNCROT_TOOL_PATH_LINES  A five-axis part program's motion blocks as CL points or machine axes.
%   [P, kinds] = cncrot_tool_path_lines(dialect, lines)
%   [axes, kinds] = cncrot_tool_path_lines(dialect, lines, machine, L)
%   [axes, kinds] = cncrot_tool_path_lines(dialect, lines, machine, L, previous, rule, ref)
%   dialect: 'sinumerik', 'heidenhain', 'fanuc', 'syntec' or 'haas' (or its code); lines: a
%   program's blocks (a cell array of char rows, a string array, or one block), read in
%   order as the control keeps the five-axis transformation: SINUMERIK TRAORI / TRAFOOF with
%   A3 B3 C3 (the tool direction), A2 B2 C2 (after ORIEULER or ORIRPY) or rotary positions;
%   Heidenhain M128 / FUNCTION TCPM with L blocks (A B C positions, IX... incremental) and LN
%   blocks (TX TY TZ); Fanuc and Syntec G43.4 (A B C) and G43.5 (I J K), Haas G234; G90/G91.
%   P is N-by-9, one row per line: the tip x y z, the tool direction i j k (NaN when the
%   block states rotary positions) and the positions a b c by letter (NaN when it states a
%   direction); NaN rows for lines that are not points. kinds (N-by-1 cell) says for each
%   line 'point' (a move with the transformation on), 'applied' (a state change: the
%   transformation, an angle mode, a move with it off), 'passed' or 'not followed' (an arc,
%   a reference move, a value that is not a number: not taken).
%   With a machine (as in cncrot_machine_forward) and the tool length L (mm): axes is
%   N-by-6, the machine's X Y Z and rotary positions for each point (as
%   cncrot_machine_tcp_inverse: the first point's solution by rule 'closest', 'minus',
%   'plus', 'inverse', 'positive_turn', 'negative_turn' or 'master_first' with ref, from
%   previous; the points after it continuous with it), NaN rows elsewhere.
%   Rotary
%   positions stated by letter go to the machine axis whose direction is nearest (A for X,
%   B for Y, C for Z).
%
%   Example (an AC table, A about X through z = 100, C on it; tool 50 mm):
%     prog = {'G43.4 H1', 'G1 X10. Y0. Z0. A30. C90.'};
%     ax = cncrot_tool_path_lines('fanuc', prog, [1 1 0 0 0 0 100 0 0 0 0 0; 1 0 0 1 0 0 0 0 0 0 0 0], 50)
%     % ax(2,:) = [0 50+5*sqrt(3) 155-50*sqrt(3) 30 90 0]
%
%   See also CNCROT_MACHINE_TCP_INVERSE, CNCROT_PROGRAM_LINES.
