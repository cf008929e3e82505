Call Missing;
