MODULE m
  VAR robtarget p := [[100, 0, 300], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST robtarget path{2} := [[[0, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], [[10, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]]];
PROC main()
  VAR num height := 20;
  p := Offs(p, 10, 0, 0);
  p.trans.z := p.trans.z + height;
  MoveJ p, v100, z10, tool0;
  WHILE TRUE DO
    IF DInput(di1) = 1 MoveL path{2}, v100, fine, tool0;
    go path{1} \dz:=5;
  ENDWHILE
ERROR
  RETRY;
ENDPROC
PROC go(robtarget t, \num dz)
  MoveL Offs(t, 0, 0, dz), v100, fine, tool0;
ENDPROC
ENDMODULE
