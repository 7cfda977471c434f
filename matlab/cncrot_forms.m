function f = cncrot_forms()
% CNCROT_FORMS  The codes of the dialects' tilted-plane forms, with their selector and words.
%   f = cncrot_forms() returns a struct whose fields are the form codes of
%   cncrot_form_frame and cncrot_form_values (the C constants CNCROT_FORM_*):
%     CYCLE800        selector _MODE;              words _X0 _Y0 _Z0 _A _B _C _X1 _Y1 _Z1
%     SINUMERIK_ROT   selector 0 RPY, 1 Euler;     words X Y Z
%     SINUMERIK_ROTS  selector 0 XY, 1 YZ, 2 ZX;   words the two angles (frame only)
%     PLANE_SPATIAL   selector 0;                  words SPA SPB SPC
%     PLANE_EULER     selector 0;                  words EULPR EULNU EULROT
%     PLANE_VECTOR    selector 0;                  words BX BY BZ NX NY NZ
%     PLANE_POINTS    selector 0;                  words P1X P1Y P1Z P2X P2Y P2Z P3X P3Y P3Z
%     G68_2           selector 0;                  words X Y Z I J K
%     G158            selector the P word;         words X Y Z A B C U V W
%     TWINCAT_ROT     selector 0;                  words X Y Z
%     G268            selector the Q word;         words X Y Z I J K
%     G68_3           selector 0;                  words X Y Z R TX TY TZ (T: tool direction)
%     PLANE_PROJECTED selector 0;                  words PROPR PROMIN PROROT
%
%   cncrot_form_frame and cncrot_form_values take the field names as well, in lower or
%   upper case, char or string, with ' ', '.' or '-' for '_': 'g68_2', 'G68.2', 'PLANE
%   SPATIAL', 'sinumerik_rot', ...
%
%   Example: F = cncrot_form_frame(cncrot_forms().G68_2, 0, [10 0 0 0 30 0])
%            F = cncrot_form_frame('G68.2', 0, [10 0 0 0 30 0])   % the same
%
%   See also CNCROT_FORM_FRAME, CNCROT_FORM_VALUES, CNCROT_DIALECTS.
  f = struct('CYCLE800', 1, 'SINUMERIK_ROT', 2, 'SINUMERIK_ROTS', 3, 'PLANE_SPATIAL', 4, ...
             'PLANE_EULER', 5, 'PLANE_VECTOR', 6, 'PLANE_POINTS', 7, 'G68_2', 8, 'G158', 9, ...
             'TWINCAT_ROT', 10, 'G268', 11, 'G68_3', 12, 'PLANE_PROJECTED', 13);
end
