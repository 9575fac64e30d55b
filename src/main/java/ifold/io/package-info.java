/** Files written whole or not at all. Plain Java. */
package ifold.io;
