% CNCROT_FORM_FRAME  Frames (4-by-4) of a controller's tilted-plane command.
%   F = cncrot_form_frame(form, selector, words)
%   form: the command, by name or code (cncrot_forms lists them): 'g68_2' (or 'G68.2'),
%   'g68_3', 'plane_spatial' (or 'PLANE SPATIAL'), 'plane_euler', 'plane_vector',
%   'plane_points', 'plane_projected', 'cycle800', 'sinumerik_rot', 'sinumerik_rots',
%   'g158', 'g268', 'twincat_rot'; any case, char or string, with ' ', '.' or '-' for '_'.
%   selector: the command's integer word (_MODE, P, Q, the angle mode, or 0), of any numeric
%   class; words: N-by-count, one command per row, its words in the order cncrot_forms lists
%   (omitted words are 0).
%   F: 4-by-4 (N = 1) or 4-by-4-by-N; a point q of the new system is F*[q; 1] in the old one.
%   Errors (the message names the argument): cncrot:badArgument (form, selector),
%   cncrot:badSequence (an axis order in the selector), cncrot:notFinite, cncrot:degenerate
%   (PLANE VECTOR/POINTS that define no plane), cncrot:notAvailable (direct modes: need the
%   machine's kinematics), cncrot:badSize, ...
%
%   Example (G68.2 X10 I0 J30 K0):
%     F = cncrot_form_frame('G68.2', 0, [10 0 0 0 30 0])
%     F = cncrot_form_frame(cncrot_forms().G68_2, 0, [10 0 0 0 30 0])   % the same
%
%   See also CNCROT_FORM_VALUES, CNCROT_FORMS, CNCROT_PROGRAM_LINES.
