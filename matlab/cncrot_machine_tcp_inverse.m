% CNCROT_MACHINE_TCP_INVERSE  Every machine axis for tool tips and directions (a path).
%   AXES = cncrot_machine_tcp_inverse(MACHINE, P, L) gives the N-by-6 machine axes — X Y Z
%   (mm, the tool adapter's reference point) then the rotary positions (degrees, unused
%   axes 0) — that put the tip of a tool of length L (mm) where P asks, with its direction:
%     P 4-by-4-by-N   poses in workpiece coordinates (tip P(1:3,4), direction P(1:3,3));
%                     with three rotary axes the whole rotation is matched;
%     P N-by-6        CL rows [x y z i j k]: tip and direction (any length, not zero);
%                     each row's frame has X' along the part of the machine's X (of Y for
%                     a direction near X) perpendicular to the direction, as cncrot path;
%                     with three rotary axes X' is carried from the orientation where the
%                     machine stands (cncrot_cl_pose(CL, P0)): no jump in the turn about
%                     the tool.
%   Each row starts from the row before (the first from PREVIOUS), so the rotary axes move
%   continuously: whole turns unwound, travel limits kept, and at a pole the free axis
%   stays where it was.
%   AXES = cncrot_machine_tcp_inverse(MACHINE, P, L, PREVIOUS) starts from PREVIOUS
%   (1-by-6, default zeros).
%   AXES = cncrot_machine_tcp_inverse(MACHINE, P, L, PREVIOUS, RULE, REF) picks the first
%   row's rotary solution by RULE as cncrot_machine_choose does, the rows after it
%   continuous with it: 'closest' (the default: the one continuous with PREVIOUS), 'minus' /
%   'plus' with REF a priority axis (1-based: its lower / higher angle in (-180, 180], as
%   SEQ-/SEQ+ ask), 'master_first' (it turns the least, then the others: Fanuc's G53.1),
%   'positive_turn' / 'negative_turn' (that axis turns only up / only down, as G53.1 P1/P2
%   ask), 'inverse' (the other solution than the one continuous with PREVIOUS). Taken again
%   at each row, a side or a direction of travel would swap branches where the axis passes
%   0: one row per call does that.
%   [AXES, STATUS] = ... also gives each row's status: 0, 2 (a free axis kept), 3 (a Hirth
%   axis snapped). A row the machine cannot reach raises an error naming the row.
%
%   Example (the AC table of cncrot_machine_tcp_forward):
%     ac = [1 1 0 0 0 0 100 0 0 0 0 0; 1 0 0 1 0 0 0 0 0 0 0 0];
%     A = cncrot_machine_tcp_inverse(ac, [10 0 0 0.5 0 sqrt(3)/2], 50, [0 0 0 20 80 0])
%     % A = [0 58.6603 68.3975 30 90 0]
%
%   See also CNCROT_MACHINE_TCP_FORWARD, CNCROT_MACHINE_CHOOSE.
