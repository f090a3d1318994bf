// Reads an LCM log and decodes every message on one channel as houghloc.pose_hypotheses_t
// with the generated houghloc_lcm_types.jar; prints "<count> <utime of first> <x of first>".
//   java -cp lcm.jar:houghloc_lcm_types.jar:. DecodeHypotheses LOG CHANNEL
import java.io.IOException;
import lcm.logging.Log;

public class DecodeHypotheses {
  public static void main(String[] args) throws IOException {
    Log log = new Log(args[0], "r");
    int count = 0;
    long firstUtime = 0;
    double firstX = Double.NaN;
    while (true) {
      Log.Event event;
      try {
        event = log.readNext();
      } catch (java.io.EOFException end) {
        break;
      }
      if (!event.channel.equals(args[1])) continue;
      houghloc.pose_hypotheses_t msg = new houghloc.pose_hypotheses_t(event.data);
      if (count == 0) {
        firstUtime = msg.utime;
        firstX = msg.num_hypotheses > 0 ? msg.hypotheses[0].x : Double.NaN;
      }
      ++count;
    }
    System.out.println(count + " " + firstUtime + " " + firstX);
  }
}
