% octave-cli time_flash.m FLASH_MFILE_DIR MESH.off [REPEATS]: the least time of FLASH's
% spherical_conformal_map(v, f) over REPEATS runs (default 3), algorithm only (the file read
% before the clock starts), printed as "flash_ms T" after "vertices N".
args = argv();
addpath(args{1});
addpath(fileparts(mfilename('fullpath')));
[v, f] = read_off(args{2});
repeats = 3;
if numel(args) > 2, repeats = str2double(args{3}); end
least = inf;
for r = 1:repeats
  start = tic;
  map = spherical_conformal_map(v, f);
  least = min(least, toc(start));
end
printf('vertices %d\nflash_ms %.1f\n', size(v, 1), 1000 * least);
