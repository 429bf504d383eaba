/* What a forager reports its finds to: the loop functions, when they are one (pose_log). The
 * controller finds the board through CSimulator::GetInstance().GetLoopFunctions(). */
#ifndef FIND_BOARD_H
#define FIND_BOARD_H

class CFindBoard {
 public:
  virtual ~CFindBoard() {}
  /* Called from ControlStep, on any thread. */
  virtual void ReportFind() = 0;
};

#endif
