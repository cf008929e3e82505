Macro M
  Call M;
Return
Call M;
