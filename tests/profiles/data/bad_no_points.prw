! SIMPACK wheel profile without a point block
  header.begin
    version       =  1
    type          =  1                       ! 1=wheel profile
  header.end
  spline.begin
    units.len.f    = +1.000000000000000e+03
    mirror.y       =  1
  spline.end
