%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%

MODULE GlueModule
  ! GRPVSS sample: an ABB arm draws a glue bead along two lines and an arc on a part.
  PERS tooldata tGlue := [TRUE, [[0, 0, 120], [0.707106781, 0, 0.707106781, 0]],
                          [0.8, [0, 0, 60], [1, 0, 0, 0], 0, 0, 0]];
  TASK PERS wobjdata wobjTable := [FALSE, TRUE, "", [[600, -300, 200], [0.707106781, 0, 0, 0.707106781]],
                                   [[0, 0, 10], [1, 0, 0, 0]]];
  CONST jointtarget jHome := [[0, -20, 20, 0, 60, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];
  CONST robtarget pStart := [[0, 0, 50], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST robtarget pCorner{2} := [[[200, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]],
                                 [[200, 150, 0], [0, 0, 1, 0], [-1, 0, -1, 1], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]]];
  CONST robtarget pArcMid := [[100, 250, 0], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST robtarget pArcEnd := [[0, 150, 0], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  VAR speeddata vBead := [80, 30, 200, 15];
  CONST zonedata zBead := [FALSE, 3, 4.5, 4.5, 0.45, 4.5, 0.45];

  PROC main()
    MoveAbsJ jHome\NoEOffs, v1000, fine, tool0;
    MoveJ Offs(pStart, 0, 0, 100), vmax, z50, tGlue\WObj:=wobjTable;
    MoveL pStart, v200, fine, tGlue\WObj:=wobjTable;
    SetDO doGlue, 1;
    bead;
    SetDO doGlue, 0;
    MoveL RelTool(pArcEnd, 0, 0, -100 \Rz:=45), v500\V:=650, z20\Z:=25, tGlue\WObj:=wobjTable;
    MoveAbsJ jHome, v1000, fine, tool0;
  ENDPROC

  PROC bead()
    MoveL pCorner{1}, vBead, zBead, tGlue\WObj:=wobjTable;
    MoveL pCorner{2}, vBead, zBead, tGlue\WObj:=wobjTable;
    MoveC pArcMid, pArcEnd, vBead, z1, tGlue\WObj:=wobjTable;
    WaitTime 0.2;
  ENDPROC
ENDMODULE
