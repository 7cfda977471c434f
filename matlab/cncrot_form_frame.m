% CNCROT_FORM_FRAME  Frames (4-by-4) of a controller's tilted-plane command.
%   F = cncrot_form_frame(form, selector, words)
%   form: a code of cncrot_forms (G68.2, G68.3, PLANE SPATIAL, CYCLE800, G158, G268, ...);
%   selector: the command's integer word (_MODE, P, Q, the angle mode, or 0); words: N-by-count,
%   one command per row, its words in the order cncrot_forms lists (omitted words are 0).
%   F: 4-by-4 (N = 1) or 4-by-4-by-N; a point q of the new system is F*[q; 1] in the old one.
%   Errors: cncrot:badArgument (form, selector), cncrot:badSequence, cncrot:notFinite,
%   cncrot:degenerate (PLANE VECTOR/POINTS that define no plane), cncrot:notAvailable
%   (direct modes: need the machine's kinematics), cncrot:badSize, ...
%
%   Example (G68.2 X10 I0 J30 K0):
%     F = cncrot_form_frame(cncrot_forms().G68_2, 0, [10 0 0 0 30 0])
