MODULE sixaxis_movel
  ! GRPVSS test program (tests/app/program_cli_test.cpp) for the six-axis demo robot of
  ! data/sixaxis/cell.yaml: MoveL up by 50 mm from a robtarget and back. pPick is the URDF's own
  ! FK of (0.3, -0.4, 0.5, 0.6, -0.7, 0.2) rad: tool0 in the robot base, mm and quaternion;
  ! confdata [0, 0, 0, 1] (axis 5 < 0).
  CONST robtarget pPick := [[345.7105, 68.8649, 857.2461], [0.7912311399, 0.2512243873, 0.4588517661, 0.3166933015], [0, 0, 0, 1], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST robtarget pAbove := [[345.7105, 68.8649, 907.2461], [0.7912311399, 0.2512243873, 0.4588517661, 0.3166933015], [0, 0, 0, 1], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    MoveAbsJ [[20, -10, 10, 0, 20, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
    MoveJ pPick, v1000, fine, tool0;
    MoveL pAbove, v200, fine, tool0;
    MoveL pPick, v100, fine, tool0;
    MoveAbsJ [[0, 0, 0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
  ENDPROC
ENDMODULE
