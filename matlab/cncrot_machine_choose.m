% CNCROT_MACHINE_CHOOSE  The rotary-axis positions to move to for an orientation.
%   [AXES, REMAINING, RESIDUAL, STATUS] = cncrot_machine_choose(MACHINE, F, CURRENT, RULE, REF)
%   brings every solution to the whole turn nearest to the CURRENT positions (computed 10,
%   current 750 -> 730) or within the travel limits, snaps Hirth axes to their grid, skips
%   solutions outside the travel, and picks one by RULE: 0 the closest (default), 1 the
%   lower and 2 the higher angle, in (-180, 180], of axis REF (1-based; CYCLE800 minus/plus, Heidenhain
%   SEQ-/SEQ+ on the master axis), 3 the other solution of the pair (CYCLE600 _ROT_INV),
%   4 / 5 axis REF turning only up / only down from its current position, the least it
%   must (G53.1 P1 / P2; the other axes the nearest turn), 6 axis REF turning the least,
%   then the others, then each nearest 0 (Fanuc's G53.1).
%   RULE may be given by name, in any case, char or string: 'closest' (0), 'minus' (1),
%   'plus' (2), 'inverse' (3), 'positive_turn' (4), 'negative_turn' (5), 'master_first'
%   (6); a blank may stand for '_'; RULE and REF may
%   be of any numeric class. REF is 0 (or left out) for 'closest' and 'inverse'.
%   REMAINING is the 4-by-4 rotation the axes leave to the frame (about the tool axis with
%   fewer than three axes, plus the Hirth residual), RESIDUAL the Hirth snapping per axis,
%   STATUS 0, 2 (a free axis kept at its current position) or 3 (snapped).
%   MACHINE as in CNCROT_MACHINE_FORWARD. Errors: cncrot:unreachable, cncrot:outOfTravel,
%   cncrot:badArgument (a rule, a REF that does not suit the rule), ...; the message names
%   the argument.
%
%   Example:
%     head = [0 0 0 1 0 0 0 0 0 0 0 0; 0 0 1 0 0 0 150 -100 100 0 0 0];
%     F = cncrot_machine_forward(head, [30 40 0]);
%     a = cncrot_machine_choose(head, F, [750 0 0]);        % [750 40 0]
%     b = cncrot_machine_choose(head, F, [0 0 0], 'minus', 2);   % [-150 -40 0]
%     b = cncrot_machine_choose(head, F, [0 0 0], 1, 2);         % the same
%
%   See also CNCROT_MACHINE_FORWARD, CNCROT_MACHINE_INVERSE, CYCLE600.
