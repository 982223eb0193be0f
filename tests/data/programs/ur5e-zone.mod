MODULE ur5e_zone
  ! A MoveAbsJ with zone z10: refused, the blended corner is not modelled
  ! (tests/app/program_cli_test.cpp). Joint values in degrees, the UR5e's order.
  CONST jointtarget jApproach := [[-30, -90, 90, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    MoveAbsJ jApproach, v100, z10, tool0;
    MoveAbsJ [[0, -90, 90, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v100, fine, tool0;
  ENDPROC
ENDMODULE
